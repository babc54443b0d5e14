#include "IoTestSupport.h"
#include "io/AtomicFile.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

namespace {

void putFile(const QString &path, const QByteArray &data)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QCOMPARE(f.write(data), data.size());
}

QByteArray content(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<unreadable>");
}

QStringList entries(const QString &dir)
{
    return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

} // namespace

class TestAtomicFile : public QObject
{
    Q_OBJECT

private slots:
    void write_createsTheFile();
    void write_replacesAnExistingFile_andLeavesNoTemporaryFile();
    void write_whereParentIsARegularFile_reportsPathAndReason();
    void write_intoMissingFolder_reportsPathAndCreatesNothing();
    void writeMany_writesEveryFile();
    void writeMany_oneFailure_keepsTheOldFiles();
    void writeMany_samePathTwice_writesNothing();
    void read_returnsTheContent();
    void read_missingFile_reportsPathAndReason();
    void read_folder_reportsPathAndReason();
};

void TestAtomicFile::write_createsTheFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.json"));
    writeFileAtomically(path, "hello\n");
    QCOMPARE(content(path), QByteArray("hello\n"));
}

void TestAtomicFile::write_replacesAnExistingFile_andLeavesNoTemporaryFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.json"));
    putFile(path, "old content that is longer");
    writeFileAtomically(path, "new");
    QCOMPARE(content(path), QByteArray("new"));
    QCOMPARE(entries(dir.path()), QStringList{QStringLiteral("a.json")});
}

void TestAtomicFile::write_whereParentIsARegularFile_reportsPathAndReason()
{
    // Root may write anywhere, so a failure comes from the path itself: "plain" is a file.
    QTemporaryDir dir;
    putFile(dir.filePath(QStringLiteral("plain")), "keep");
    const QString path = dir.filePath(QStringLiteral("plain/out.json"));
    const QString message = test::errorOf([&] { writeFileAtomically(path, "x"); });
    QVERIFY2(message.startsWith(QStringLiteral("cannot write %1: ").arg(path)),
             qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("Not a directory")), qPrintable(message));
    QCOMPARE(content(dir.filePath(QStringLiteral("plain"))), QByteArray("keep"));
    QCOMPARE(entries(dir.path()), QStringList{QStringLiteral("plain")});
}

void TestAtomicFile::write_intoMissingFolder_reportsPathAndCreatesNothing()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("missing/out.json"));
    const QString message = test::errorOf([&] { writeFileAtomically(path, "x"); });
    QVERIFY2(message.contains(path), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("No such file or directory")), qPrintable(message));
    QVERIFY(entries(dir.path()).isEmpty());
}

void TestAtomicFile::writeMany_writesEveryFile()
{
    QTemporaryDir dir;
    const QString a = dir.filePath(QStringLiteral("a")), b = dir.filePath(QStringLiteral("b"));
    putFile(a, "old a");
    writeFilesAtomically({{a, "new a"}, {b, "new b"}});
    QCOMPARE(content(a), QByteArray("new a"));
    QCOMPARE(content(b), QByteArray("new b"));
    QCOMPARE(entries(dir.path()), (QStringList{QStringLiteral("a"), QStringLiteral("b")}));
}

void TestAtomicFile::writeMany_oneFailure_keepsTheOldFiles()
{
    QTemporaryDir dir;
    const QString a = dir.filePath(QStringLiteral("a.json"));
    const QString c = dir.filePath(QStringLiteral("c.csv"));
    const QString bad = dir.filePath(QStringLiteral("a.json/b.dcf")); // parent is a file
    putFile(a, "old a");
    const QString message = test::errorOf([&] {
        writeFilesAtomically({{a, "new a"}, {bad, "b"}, {c, "new c"}});
    });
    QVERIFY2(message.startsWith(QStringLiteral("cannot write %1: ").arg(bad)), qPrintable(message));
    QCOMPARE(content(a), QByteArray("old a"));
    QCOMPARE(entries(dir.path()), QStringList{QStringLiteral("a.json")}); // no c, no temporaries
}

void TestAtomicFile::writeMany_samePathTwice_writesNothing()
{
    QTemporaryDir dir;
    const QString a = dir.filePath(QStringLiteral("a"));
    LEARNID_VERIFY_ERROR(
        writeFilesAtomically({{a, "1"}, {dir.path() + QStringLiteral("/./a"), "2"}}),
        QStringLiteral("the same file is to be written twice"));
    QVERIFY(entries(dir.path()).isEmpty());
}

void TestAtomicFile::read_returnsTheContent()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("r"));
    putFile(path, QByteArray("bytes\0inside", 12));
    QCOMPARE(readFile(path), QByteArray("bytes\0inside", 12));
}

void TestAtomicFile::read_missingFile_reportsPathAndReason()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("none.json"));
    QCOMPARE(test::errorOf([&] { readFile(path); }),
             QStringLiteral("cannot read %1: No such file or directory").arg(path));
}

void TestAtomicFile::read_folder_reportsPathAndReason()
{
    QTemporaryDir dir;
    const QString message = test::errorOf([&] { readFile(dir.path()); });
    QVERIFY2(message.startsWith(QStringLiteral("cannot read %1: ").arg(dir.path())),
             qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("directory")), qPrintable(message));
}

QTEST_GUILESS_MAIN(TestAtomicFile)
#include "tst_atomicfile.moc"
