// SPDX-License-Identifier: MIT
#pragma once

/// A place in a text file; zero-based internally, printed one-based. Invalid (line -1) when a
/// value was not read from a file.
struct TextPos
{
    int line = -1;
    int column = -1;
    bool isValid() const { return line >= 0; }
    bool operator==(const TextPos& o) const { return line == o.line && column == o.column; }
};
