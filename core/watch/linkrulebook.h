// SPDX-License-Identifier: MIT
#pragma once

#include "watch/linkdef.h"
#include "watch/watchrules.h"

/// The watch's rules, and how often a link's rules were looked up in them (every override matched
/// against a link): the bounded work of a change of links or rules.
class LinkRuleBook
{
public:
    void set(const WatchRules& rules) { m_rules = rules; }
    const WatchRules& rules() const { return m_rules; }
    quint64 lookups() const { return m_lookups; }
    /// The rules of `def`, counted as one lookup.
    LinkRules forLink(const LinkDef& def)
    {
        ++m_lookups;
        return m_rules.forLink(def.key());
    }

private:
    WatchRules m_rules;
    quint64 m_lookups = 0;
};
