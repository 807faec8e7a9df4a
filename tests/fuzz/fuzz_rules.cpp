// SPDX-License-Identifier: MIT
// Fuzz target for the watch rules reader (`watch --rules`, the Links page), WatchRules::read.
//
// Input: a rules YAML, and after a NUL byte a link name matched against its patterns. Properties:
// a rejected file says why; an accepted one is within the limits (entries, pattern length); what
// it writes it reads back and writes the same (for printable patterns); matching any name against
// every pattern ends (glob, no regular expression).
#include "fuzzcheck.h"
#include "watch/watchrules.h"

namespace {
bool printable(const QString& text)
{
    for (const QChar c : text)
        if (!c.isPrint() || c == QChar(0x85) || c == QChar(0x2028) || c == QChar(0x2029))
            return false;
    return true;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const auto [yaml, nameBytes] = fuzz::splitAtNul(fuzz::bytes(data, size));
    const Result<WatchRules> rules = WatchRules::read(yaml);
    if (!rules) {
        FUZZ_CHECK(!rules.error().toString().isEmpty(), "rules rejected without a reason");
        return 0;
    }
    FUZZ_CHECK(rules->overrides.size() <= WatchRules::kMaxLinkRules, "more entries than the limit");
    bool allPrintable = true;
    for (const WatchRules::Override& o : rules->overrides) {
        FUZZ_CHECK(!o.match.isEmpty() && o.match.size() <= WatchRules::kMaxPatternChars,
                   "a pattern past the limit");
        allPrintable = allPrintable && printable(o.match);
    }
    const QString name = QString::fromUtf8(nameBytes);
    const LinkRules r = rules->forLink({name, name, name, name});
    for (const Threshold& t : r.thresholds)
        FUZZ_CHECK((std::isnan(t.warning) || t.warning >= 0) && (std::isnan(t.alert) || t.alert >= 0),
                   "a negative level");
    if (allPrintable) {
        const QByteArray written = rules->toYaml();
        const Result<WatchRules> again = WatchRules::read(written);
        FUZZ_CHECK(again, "what the rules write does not read back");
        FUZZ_CHECK(again->toYaml() == written, "what the rules write reads back otherwise");
    }
    return 0;
}
