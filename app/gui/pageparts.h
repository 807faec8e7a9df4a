// SPDX-License-Identifier: MIT
#pragma once

#include "widgets/discover/detailpane.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/map/mappage.h"

class LiveSession;

/// The parts of a live session the window's pages take, built here where the window is composed
/// (and by tests that build a page), so that no page sees the session.
namespace PageParts {
DetailPane::Parts detail(LiveSession* live);
DiscoverPage::Parts discover(LiveSession* live);
MapPage::Parts map(LiveSession* live);
} // namespace PageParts
