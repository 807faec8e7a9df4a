// SPDX-License-Identifier: MIT
// bridgescope-bagreader BAG OUT.bsrun: reads a ROS bag with rosbag's library and writes its stamps
// as a run file. Its own process, because the library trusts the file: a damaged bag may crash it
// or make it allocate without end. Prints "progress N" lines; exit 0 done, 1 the bag does not read.
#include "record/runfile.h"
#include "ros/rosbagimport.h"

#include <cstdio>
#include <new>
#include <QCoreApplication>
#include <sys/resource.h>

namespace {
/// The most address space the reader may take: a bag is read chunk by chunk, and a size field
/// gone wrong must not take the machine's memory.
constexpr rlim_t kMaxAddressSpace = rlim_t(3) << 30;

void limitMemory()
{
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
    rlimit limit {kMaxAddressSpace, kMaxAddressSpace};
    setrlimit(RLIMIT_AS, &limit);
#endif
}

int fail(const QString& why)
{
    std::fprintf(stderr, "%s\n", why.toLocal8Bit().constData());
    return 1;
}
} // namespace

int main(int argc, char** argv)
{
    limitMemory();
    QCoreApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    if (args.size() != 3)
        return fail(QCoreApplication::translate("BagReader", "usage: bridgescope-bagreader BAG OUT.bsrun"));
    try {
        const Result<RunData> run = RosbagImport::read(args[1], [](int percent) {
            std::printf("progress %d\n", percent);
            std::fflush(stdout);
            return true;
        });
        if (!run)
            return fail(run.error().toString());
        if (const Result<void> written = RunFile::write(args[2], *run); !written)
            return fail(written.error().toString());
    } catch (const std::bad_alloc&) {
        return fail(QCoreApplication::translate(
            "BagReader", "the bag asks for more memory than a bag of stamps needs: it is damaged"));
    } catch (const std::exception& e) {
        return fail(QCoreApplication::translate("BagReader", "cannot read the bag: %1")
                        .arg(QString::fromLocal8Bit(e.what())));
    }
    return 0;
}
