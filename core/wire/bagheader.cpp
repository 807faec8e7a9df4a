// SPDX-License-Identifier: MIT
#include "bagheader.h"

#include <QFile>
#include <QFileInfo>

bool BagHeader::looksLikeBag(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) && f.read(13) == "#ROSBAG V2.0\n";
}

QString BagHeader::refusal(const QString& path)
{
    if (!QFileInfo(path).isReadable())
        return tr("cannot read it");
    if (!looksLikeBag(path))
        return tr("not a ROS 1 bag (no #ROSBAG V2.0 header)");
    return {};
}
