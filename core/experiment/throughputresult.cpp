// SPDX-License-Identifier: MIT
#include "experiment/throughputresult.h"

#include <algorithm>
#include <QJsonArray>

using namespace Qt::StringLiterals;

double ThroughputResult::maxSustainableHz() const
{
    double best = 0;
    for (const ThroughputPoint& p : points)
        if (p.sustainable)
            best = std::max(best, p.rateHz);
    return best;
}

QJsonObject ThroughputResult::toJson() const
{
    QJsonArray rates;
    for (const ThroughputPoint& p : points)
        rates.append(QJsonObject {{u"rate_hz"_s, p.rateHz},
                                  {u"samples"_s, double(p.samples)},
                                  {u"expected"_s, double(p.expected)},
                                  {u"dropped"_s, double(p.dropped)},
                                  {u"p50_ms"_s, p.p50Ms},
                                  {u"p99_ms"_s, p.p99Ms},
                                  {u"sustainable"_s, p.sustainable}});
    return {{u"payload_bytes"_s, payloadBytes},
            {u"level"_s, level},
            {u"complete"_s, complete},
            {u"max_sustainable_hz"_s, maxSustainableHz()},
            {u"mb_per_s"_s, megabytesPerSecond()},
            {u"rates"_s, rates}};
}

ThroughputResult ThroughputResult::fromJson(const QJsonObject& o)
{
    ThroughputResult r;
    r.payloadBytes = o.value(u"payload_bytes"_s).toInt();
    r.level = o.value(u"level"_s).toString().left(256);
    r.complete = o.value(u"complete"_s).toBool();
    for (const QJsonValue& pv : o.value(u"rates"_s).toArray()) {
        const QJsonObject po = pv.toObject();
        ThroughputPoint p;
        p.rateHz = po.value(u"rate_hz"_s).toDouble();
        p.samples = po.value(u"samples"_s).toInteger();
        p.expected = po.value(u"expected"_s).toInteger();
        p.dropped = po.value(u"dropped"_s).toInteger();
        p.p50Ms = po.value(u"p50_ms"_s).toDouble();
        p.p99Ms = po.value(u"p99_ms"_s).toDouble();
        p.sustainable = po.value(u"sustainable"_s).toBool();
        if (r.points.size() < kMaxPoints)
            r.points << p;
    }
    return r;
}
