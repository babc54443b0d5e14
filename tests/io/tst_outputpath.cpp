#include "IoTestSupport.h"
#include "io/OutputPath.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

namespace {

const QString what = QStringLiteral("--report");

} // namespace

class TestOutputPath : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void relativePath_isTakenFromTheBaseFolder();
    void notYetExistingFolders_areAccepted();
    void pathsOutsideTheBase_areTheUsersChoice();
    void dotDot_isLeftForTheSystemToWalk();
    void missingBase_isRejectedForARelativePath();
    void emptyPath_isRejected();

private:
    QString base() const { return QDir(m_root->path()).canonicalPath() + QStringLiteral("/ws"); }

    std::unique_ptr<QTemporaryDir> m_root;
};

void TestOutputPath::init()
{
    m_root = std::make_unique<QTemporaryDir>();
    QVERIFY(m_root->isValid());
    QVERIFY(QDir().mkpath(base() + QStringLiteral("/sub")));
}

void TestOutputPath::relativePath_isTakenFromTheBaseFolder()
{
    QCOMPARE(resolveOutputPath(base(), QStringLiteral("out.json"), what),
             base() + QStringLiteral("/out.json"));
    QCOMPARE(resolveOutputPath(base(), QStringLiteral("./sub//out.json"), what),
             base() + QStringLiteral("/sub/out.json"));
}

void TestOutputPath::notYetExistingFolders_areAccepted()
{
    QCOMPARE(resolveOutputPath(base(), QStringLiteral("new/trials"), what),
             base() + QStringLiteral("/new/trials"));
}

void TestOutputPath::pathsOutsideTheBase_areTheUsersChoice()
{
    const QString elsewhere = QDir(m_root->path()).canonicalPath() + QStringLiteral("/r.json");
    QCOMPARE(resolveOutputPath(base(), elsewhere, what), elsewhere);
    QCOMPARE(resolveOutputPath(base(), QStringLiteral("/tmp/r.json"), what),
             QStringLiteral("/tmp/r.json"));
}

void TestOutputPath::dotDot_isLeftForTheSystemToWalk()
{
    // base/jump -> other/a/b: "jump/../x.json" is other/a/x.json for the system; a lexical
    // clean would make it base/x.json. The resolved path must land where the system writes.
    const QString other = QDir(m_root->path()).canonicalPath() + QStringLiteral("/other");
    QVERIFY(QDir().mkpath(other + QStringLiteral("/a/b")));
    QVERIFY(QFile::link(other + QStringLiteral("/a/b"), base() + QStringLiteral("/jump")));
    const QString resolved = resolveOutputPath(base(), QStringLiteral("jump/../x.json"), what);
    QFile f(resolved);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.close();
    QVERIFY(QFile::exists(other + QStringLiteral("/a/x.json")));
    QVERIFY(!QFile::exists(base() + QStringLiteral("/x.json")));
    QCOMPARE(resolveOutputPath(base(), QStringLiteral("../up.json"), what),
             base() + QStringLiteral("/../up.json"));
}

void TestOutputPath::missingBase_isRejectedForARelativePath()
{
    LEARNID_VERIFY_ERROR(
        resolveOutputPath(QStringLiteral("/nonexistent/ws"), QStringLiteral("r.json"), what),
        QStringLiteral("--report: r.json is relative, and the folder it is taken from, "
                       "/nonexistent/ws, does not exist or is not a folder"));
    QCOMPARE(
        resolveOutputPath(QStringLiteral("/nonexistent/ws"), QStringLiteral("/tmp/r.json"), what),
        QStringLiteral("/tmp/r.json"));
}

void TestOutputPath::emptyPath_isRejected()
{
    LEARNID_VERIFY_ERROR(resolveOutputPath(base(), QString(), what),
                         QStringLiteral("--report: no path given"));
}

QTEST_GUILESS_MAIN(TestOutputPath)
#include "tst_outputpath.moc"
