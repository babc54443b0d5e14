#pragma once

// Test support: the recorded robot data beside the repository (../shared/data, DESIGN.md):
// read in place, never copied. LEARNID_DATA overrides where they are.

#include <QDir>
#include <QFileInfo>
#include <QString>

#ifndef LEARNID_SHARED_DATA
#error "tests/CMakeLists.txt defines LEARNID_SHARED_DATA"
#endif

namespace learnid::test {

inline QString sharedDataDir()
{
    const QString set = qEnvironmentVariable("LEARNID_DATA");
    return set.isEmpty() ? QStringLiteral(LEARNID_SHARED_DATA) : set;
}

/// The file's path under the data directory, or empty when it is not there.
inline QString sharedDataFile(const QString &relative)
{
    const QString path = QDir(sharedDataDir()).filePath(relative);
    return QFileInfo::exists(path) ? path : QString();
}

/// Why a test that needs the data is skipped without them.
inline QString sharedDataMissing()
{
    return QStringLiteral("the recorded robot data are not at %1 (the shared/data directory "
                          "beside the repository; set LEARNID_DATA to where they are)")
        .arg(sharedDataDir());
}

} // namespace learnid::test
