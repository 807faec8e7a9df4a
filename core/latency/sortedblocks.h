// SPDX-License-Identifier: MIT
#pragma once

#include <QtGlobal>
#include <utility>
#include <vector>

/// A sorted multiset of integers in blocks of at most a thousand values.
///
/// Insert and erase cost a binary search and a short memmove (O(log n + block)), never a re-sort;
/// rank and order-statistic queries cost a binary search. This keeps a window's percentiles cheap
/// per sample for 600 values and for a million alike.
class SortedBlocks
{
public:
    void insert(qint64 value);
    /// Removes one occurrence; false if the value is not there.
    bool erase(qint64 value);
    /// erase(out) and insert(in) in one move where both fall in one block (a sliding window's step).
    bool replace(qint64 out, qint64 in);
    void clear();

    qint64 size() const { return m_size; }
    bool isEmpty() const { return m_size == 0; }
    /// The value of rank `k` (0: the smallest); k must be in [0, size).
    qint64 at(qint64 k) const;
    /// The values of rank k and k+1 (or k again at the end): one search for an interpolation.
    std::pair<qint64, qint64> atPair(qint64 k) const;
    /// How many values are below `value`.
    qint64 countBelow(qint64 value) const;
    /// How many values are at most `value`.
    qint64 countAtMost(qint64 value) const;
    qint64 min() const { return m_blocks.front().front(); }
    qint64 max() const { return m_maxes.back(); }
    std::vector<qint64> toVector() const;
    int blockCount() const { return int(m_blocks.size()); }

private:
    static constexpr std::size_t kMaxBlock = 1024;
    void updatePrefix() const;
    void removeBlock(std::size_t i);

    std::vector<std::vector<qint64>> m_blocks;
    std::vector<qint64> m_maxes; ///< the last value of each block
    mutable std::vector<qint64> m_prefix; ///< values before each block
    mutable bool m_prefixDirty = false;
    qint64 m_size = 0;
};
