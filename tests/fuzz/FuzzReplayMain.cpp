// Replays inputs through a fuzz target without libFuzzer, for the normal (gcc) build: every file
// given, and every file in every directory given (sorted by name), goes through
// LLVMFuzzerTestOneInput once. Registered in CTest with the target's corpus, so the seeds and
// every crash input kept there are regression tests of each normal test run.

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStringList>
#include <cstdint>
#include <cstdio>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

namespace {

bool replay(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        std::fprintf(stderr, "cannot read %s: %s\n", qPrintable(path),
                     qPrintable(file.errorString()));
        return false;
    }
    const QByteArray input = file.readAll();
    std::fprintf(stderr, "replaying %s (%lld bytes)\n", qPrintable(path),
                 static_cast<long long>(input.size()));
    // A copy of exactly the input's size, so that reading past the end is caught by ASan.
    const QByteArray copy(input.constData(), input.size());
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t *>(copy.constData()),
                           size_t(copy.size()));
    return true;
}

} // namespace

int main(int argc, char **argv)
{
    int files = 0;
    bool ok = true;
    for (int i = 1; i < argc; ++i) {
        const QString arg = QString::fromLocal8Bit(argv[i]);
        const QFileInfo info(arg);
        if (info.isDir()) {
            const QStringList names = QDir(arg).entryList(QDir::Files, QDir::Name);
            for (const QString &name : names) {
                ok = replay(QDir(arg).filePath(name)) && ok;
                ++files;
            }
        } else {
            ok = replay(arg) && ok;
            ++files;
        }
    }
    if (files == 0) {
        std::fprintf(stderr, "usage: %s FILE_OR_DIRECTORY... (no input found)\n", argv[0]);
        return 2;
    }
    std::fprintf(stderr, "%d inputs replayed\n", files);
    return ok ? 0 : 1;
}
