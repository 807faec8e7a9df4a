// SPDX-License-Identifier: MIT
#include "stampbag.h"

#include "ros/rosstampsource.h"
#include "wire/stampcodec.h"

#include <cstring>
#include <rosbag/bag.h>

namespace StampBag {

topic_tools::ShapeShifter shaped(const char* md5, const char* type, const std::string& definition,
                                 const QByteArray& bytes)
{
    topic_tools::ShapeShifter s;
    s.morph(md5, type, definition, "");
    std::vector<uint8_t> buffer(bytes.begin(), bytes.end());
    ros::serialization::IStream in(buffer.data(), uint32_t(buffer.size()));
    s.read(in);
    return s;
}

void write(const QString& path, const SyntheticRun& synthetic)
{
    rosbag::Bag bag(path.toStdString(), rosbag::bagmode::Write);
    const std::string def = StampCodec::definition().toStdString();
    for (const auto& t : synthetic.samples) {
        for (int i = 0; i < synthetic.topics.size(); ++i) {
            StampCodec::Decoded d;
            d.sampleNs = t.front();
            d.timeNs = t[std::size_t(i)];
            const qint64 at = t[std::size_t(i)] + 500'000;
            bag.write(
                synthetic.topics[i].toStdString(),
                ros::Time(uint32_t(at / 1'000'000'000), uint32_t(at % 1'000'000'000)),
                shaped(StampCodec::md5(), StampCodec::typeName(), def, StampCodec::encodeTimeStamped(d)));
        }
        double seconds = 0.0195;
        QByteArray f64(8, Qt::Uninitialized);
        std::memcpy(f64.data(), &seconds, 8);
        const qint64 at = t.front();
        bag.write("/mqtt_client/latencies/points",
                  ros::Time(uint32_t(at / 1'000'000'000), uint32_t(at % 1'000'000'000)),
                  shaped(RosStampSource::float64Md5(), "std_msgs/Float64", "float64 data\n", f64));
        bag.write("/chatter", ros::Time(uint32_t(at / 1'000'000'000), 0),
                  shaped("992ce8a1687cec8c8bd883ec73ca41d1", "std_msgs/String", "string data\n",
                         QByteArray("\x02\0\0\0hi", 6)));
    }
}

} // namespace StampBag
