// SPDX-License-Identifier: MIT
#include "bridgeliveness.h"

bool BridgeLiveness::update(const Input& in)
{
    if (willDownNs > 0 && in.lastDataNs > willDownNs)
        willDownNs = 0; // it carries data again
    if (in.blind && willDownNs > 0 && in.nowNs - willDownNs <= 2 * kWillGraceNs)
        willDownNs = 0; // the will of a broker going down, not of the bridge
    BridgeState next = BridgeState::Unknown;
    if (in.blind)
        next = BridgeState::Unknown;
    else if (willDownNs > 0 && in.nowNs - willDownNs >= kWillGraceNs)
        next = BridgeState::Down;
    else if (in.carries)
        next = BridgeState::Up;
    else if (in.stalled)
        next = BridgeState::Down;
    if (next == state)
        return false;
    state = next;
    return true;
}

QString BridgeLiveness::detail(const QString& name) const
{
    if (state != BridgeState::Down)
        return {};
    return willDownNs > 0 ? tr("the bridge %1 left its last will").arg(name)
                          : tr("the bridge %1 carries nothing while its sources publish").arg(name);
}
