// SPDX-License-Identifier: MIT
#include "logging.h"

#include <cstring>

Q_LOGGING_CATEGORY(lcConfig, "bridgescope.config", QtInfoMsg)
Q_LOGGING_CATEGORY(lcMqtt, "bridgescope.mqtt", QtInfoMsg)
Q_LOGGING_CATEGORY(lcRos, "bridgescope.ros", QtInfoMsg)
Q_LOGGING_CATEGORY(lcRos2, "bridgescope.ros2", QtInfoMsg)
Q_LOGGING_CATEGORY(lcRecord, "bridgescope.record", QtInfoMsg)
Q_LOGGING_CATEGORY(lcReport, "bridgescope.report", QtInfoMsg)
Q_LOGGING_CATEGORY(lcBridge, "bridgescope.bridge", QtInfoMsg)
Q_LOGGING_CATEGORY(lcSession, "bridgescope.session", QtInfoMsg)
Q_LOGGING_CATEGORY(lcDemo, "bridgescope.demo", QtInfoMsg)
Q_LOGGING_CATEGORY(lcWatch, "bridgescope.watch", QtInfoMsg)

namespace Logging {

QStringList categoryNames()
{
    QStringList names;
    for (const QLoggingCategory& (*c)() :
         {lcConfig, lcMqtt, lcRos, lcRos2, lcRecord, lcReport, lcBridge, lcSession, lcDemo, lcWatch})
        names << QString::fromLatin1(c().categoryName());
    return names;
}

void enableVerbose()
{
    QLoggingCategory::setFilterRules(QStringLiteral("bridgescope.*.debug=true"));
    if (!qEnvironmentVariableIsSet("QT_MESSAGE_PATTERN"))
        qSetMessagePattern(QStringLiteral("%{time hh:mm:ss.zzz} %{category} "
                                          "%{if-debug}debug%{endif}%{if-info}info%{endif}"
                                          "%{if-warning}warning%{endif}%{if-critical}error%{endif}"
                                          "%{if-fatal}fatal%{endif}: %{message}"));
}

bool takeVerboseFlag(int* argc, char** argv)
{
    bool found = false;
    int out = 1;
    bool rest = false;
    for (int i = 1; i < *argc; ++i) {
        if (!rest && std::strcmp(argv[i], "--") == 0)
            rest = true;
        if (!rest && std::strcmp(argv[i], "--verbose") == 0) {
            found = true;
            continue;
        }
        argv[out++] = argv[i];
    }
    argv[out] = nullptr;
    *argc = out;
    return found;
}

} // namespace Logging
