// SPDX-License-Identifier: MIT
#include "rosbagimport.h"

#include "latency/pipelinediscovery.h"
#include "ros/rosstampsource.h"
#include "wire/bagheader.h"
#include "wire/stampcodec.h"

#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <rosbag/bag.h>
#include <rosbag/view.h>

using namespace Qt::StringLiterals;

Result<RunData> RosbagImport::read(const QString& path, const Progress& progress)
{
    const auto bagError = [&](const QString& why) { return LocatedError {why, {}, path}; };
    if (const QString why = BagHeader::refusal(path); !why.isEmpty())
        return bagError(why);
    RunData run;
    try {
        rosbag::Bag bag;
        bag.open(path.toStdString(), rosbag::bagmode::Read);
        const auto wanted = [](const rosbag::ConnectionInfo* c) {
            return c->datatype == StampCodec::typeName()
                || (c->datatype == "std_msgs/Float64" && c->topic.find("/latencies/") != std::string::npos);
        };
        rosbag::View view(bag, wanted);
        QStringList bagTopics;
        {
            rosbag::View all(bag);
            for (const rosbag::ConnectionInfo* c : all.getConnections())
                bagTopics << QString::fromStdString(c->topic + " (" + c->datatype + ")");
        }
        bool anyStamps = false;
        for (const rosbag::ConnectionInfo* c : view.getConnections())
            anyStamps = anyStamps || c->datatype == StampCodec::typeName();
        if (!anyStamps)
            return bagError(tr("no %1 topics in the bag (it has: %2)")
                                .arg(QLatin1StringView(StampCodec::typeName()),
                                     bagTopics.isEmpty() ? tr("nothing") : bagTopics.join(u", "_s)));
        QHash<QString, int> topicIndex;
        QHash<QString, int> seriesIndex;
        PipelineDiscovery discovery;
        std::vector<uint8_t> buffer;
        const std::size_t total = view.size();
        std::size_t n = 0;
        qint64 malformed = 0;
        for (const rosbag::MessageInstance& m : view) {
            const QString topic = QString::fromStdString(m.getTopic());
            const ros::Time t = m.getTime();
            const qint64 received = qint64(t.sec) * 1'000'000'000LL + qint64(t.nsec);
            buffer.resize(m.size());
            ros::serialization::OStream out(buffer.data(), uint32_t(buffer.size()));
            m.write(out);
            const QByteArray bytes(reinterpret_cast<const char*>(buffer.data()), qsizetype(buffer.size()));
            if (m.getDataType() == StampCodec::typeName()) {
                if (m.getMD5Sum() != StampCodec::md5()) {
                    ++malformed;
                    continue;
                }
                const Result<StampCodec::Decoded> d = StampCodec::decodeTimeStamped(bytes);
                if (!d) {
                    ++malformed;
                    continue;
                }
                auto it = topicIndex.find(topic);
                if (it == topicIndex.end()) {
                    it = topicIndex.insert(topic, int(run.topics.size()));
                    run.topics << topic;
                }
                run.stamps.push_back({*it, d->sampleNs, d->timeNs, received, received});
                discovery.add({topic, d->sampleNs, d->timeNs, received});
            } else {
                const std::optional<qint64> v = m.getMD5Sum() == RosStampSource::float64Md5()
                    ? StampCodec::decodeFloat64Seconds(bytes)
                    : std::nullopt;
                if (!v) {
                    ++malformed;
                    continue;
                }
                auto it = seriesIndex.find(topic);
                if (it == seriesIndex.end()) {
                    it = seriesIndex.insert(topic, int(run.series.size()));
                    run.series << topic;
                }
                run.latencies.push_back({*it, *v, received, received});
            }
            if (progress && ++n % 10000 == 0 && !progress(int(95 * n / std::max<std::size_t>(total, 1))))
                return bagError(tr("cancelled"));
        }
        run.info.pipeline = discovery.propose(0);
        run.info.window = 0;
        run.info.source = QFileInfo(path).absoluteFilePath();
        run.info.name = QFileInfo(path).completeBaseName();
        run.info.startedNs = qint64(view.getBeginTime().sec) * 1'000'000'000LL + view.getBeginTime().nsec;
        run.info.stoppedNs = qint64(view.getEndTime().sec) * 1'000'000'000LL + view.getEndTime().nsec;
        if (malformed)
            run.info.notes
                = tr("%1 messages of the stamp types did not decode and were skipped.").arg(malformed);
        bag.close();
    } catch (const rosbag::BagException& e) {
        return bagError(tr("cannot read the bag: %1").arg(QString::fromStdString(e.what())));
    } catch (const ros::Exception& e) {
        return bagError(tr("cannot read the bag: %1").arg(QString::fromStdString(e.what())));
    }
    if (progress)
        progress(100);
    return run;
}
