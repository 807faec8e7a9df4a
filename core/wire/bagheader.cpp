// SPDX-License-Identifier: MIT
#include "bagheader.h"

#include "files/regularfile.h"

#include <QFile>
#include <QFileInfo>

bool BagHeader::looksLikeBag(const QString& path)
{
    return RegularFile::head(path, 13) == "#ROSBAG V2.0\n";
}

QString BagHeader::refusal(const QString& path)
{
    if (const QString what = RegularFile::notAFile(path); !what.isEmpty())
        return tr("%1, not a file").arg(what);
    if (!QFileInfo(path).isReadable())
        return tr("cannot read it");
    if (!looksLikeBag(path))
        return tr("not a ROS 1 bag (no #ROSBAG V2.0 header)");
    return {};
}
