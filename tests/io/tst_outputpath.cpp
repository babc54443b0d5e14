#include "IoTestSupport.h"
#include "io/Workspace.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

namespace {

const QString what = QStringLiteral("--report");

} // namespace

class TestWorkspace : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void relativePath_resolvesInsideTheWorkspace();
    void notYetExistingFolders_areAccepted();
    void absolutePathInside_isAccepted();
    void dotDotInside_isAccepted();
    void dotDotEscape_isRejectedNamingOptionAndPath();
    void absolutePathOutside_isRejected();
    void symlinkToOutside_isRejected();
    void danglingSymlinkToOutside_isRejected();
    void relativeSymlinkUpwards_isRejected();
    void symlinkInside_isAccepted();
    void dotDotAfterSymlink_leavesTheLinkTarget();
    void workspaceGivenThroughASymlink_isAccepted();
    void missingWorkspace_isRejected();
    void emptyPath_isRejected();

private:
    QString ws() const { return QDir(m_root->path()).canonicalPath() + QStringLiteral("/ws"); }
    QString outside() const
    {
        return QDir(m_root->path()).canonicalPath() + QStringLiteral("/outside");
    }

    std::unique_ptr<QTemporaryDir> m_root;
};

void TestWorkspace::init()
{
    m_root = std::make_unique<QTemporaryDir>();
    QVERIFY(m_root->isValid());
    QVERIFY(QDir().mkpath(ws() + QStringLiteral("/sub/deeper")));
    QVERIFY(QDir().mkpath(outside()));
}

void TestWorkspace::relativePath_resolvesInsideTheWorkspace()
{
    QCOMPARE(resolveInWorkspace(ws(), QStringLiteral("out.json"), what),
             ws() + QStringLiteral("/out.json"));
    QCOMPARE(resolveInWorkspace(ws(), QStringLiteral("./sub//out.json"), what),
             ws() + QStringLiteral("/sub/out.json"));
}

void TestWorkspace::notYetExistingFolders_areAccepted()
{
    QCOMPARE(resolveInWorkspace(ws(), QStringLiteral("new/trials"), what),
             ws() + QStringLiteral("/new/trials"));
}

void TestWorkspace::absolutePathInside_isAccepted()
{
    const QString path = ws() + QStringLiteral("/sub/out.json");
    QCOMPARE(resolveInWorkspace(ws(), path, what), path);
}

void TestWorkspace::dotDotInside_isAccepted()
{
    QCOMPARE(resolveInWorkspace(ws(), QStringLiteral("sub/deeper/../../out.json"), what),
             ws() + QStringLiteral("/out.json"));
}

void TestWorkspace::dotDotEscape_isRejectedNamingOptionAndPath()
{
    const QString message = test::errorOf(
        [&] { resolveInWorkspace(ws(), QStringLiteral("sub/../../out.json"), what); });
    QVERIFY2(message.startsWith(
                 QStringLiteral("--report: sub/../../out.json is outside the workspace ")),
             qPrintable(message));
    LEARNID_VERIFY_ERROR(resolveInWorkspace(ws(), QStringLiteral("../ws2/out.json"), what),
                         QStringLiteral("is outside the workspace"));
}

void TestWorkspace::absolutePathOutside_isRejected()
{
    LEARNID_VERIFY_ERROR(resolveInWorkspace(ws(), outside() + QStringLiteral("/x.json"), what),
                         QStringLiteral("is outside the workspace"));
    LEARNID_VERIFY_ERROR(resolveInWorkspace(ws(), QStringLiteral("/etc/passwd"), what),
                         QStringLiteral("--report: /etc/passwd is outside"));
}

void TestWorkspace::symlinkToOutside_isRejected()
{
    QVERIFY(QFile::link(outside(), ws() + QStringLiteral("/link")));
    const QString message =
        test::errorOf([&] { resolveInWorkspace(ws(), QStringLiteral("link/out.json"), what); });
    QVERIFY2(message.contains(QStringLiteral("link/out.json is outside the workspace")),
             qPrintable(message));
    QVERIFY2(message.contains(outside() + QStringLiteral("/out.json")), qPrintable(message));
}

void TestWorkspace::danglingSymlinkToOutside_isRejected()
{
    // Writing through it would create the target outside.
    QVERIFY(
        QFile::link(outside() + QStringLiteral("/new.json"), ws() + QStringLiteral("/out.json")));
    LEARNID_VERIFY_ERROR(resolveInWorkspace(ws(), QStringLiteral("out.json"), what),
                         QStringLiteral("is outside the workspace"));
}

void TestWorkspace::relativeSymlinkUpwards_isRejected()
{
    QVERIFY(QFile::link(QStringLiteral("../../outside"), ws() + QStringLiteral("/sub/up")));
    LEARNID_VERIFY_ERROR(resolveInWorkspace(ws(), QStringLiteral("sub/up/x.csv"), what),
                         QStringLiteral("is outside the workspace"));
}

void TestWorkspace::symlinkInside_isAccepted()
{
    QVERIFY(QFile::link(QStringLiteral("sub/deeper"), ws() + QStringLiteral("/short")));
    QCOMPARE(resolveInWorkspace(ws(), QStringLiteral("short/out.json"), what),
             ws() + QStringLiteral("/sub/deeper/out.json"));
}

void TestWorkspace::dotDotAfterSymlink_leavesTheLinkTarget()
{
    // ws/jump -> outside/a/b: "jump/../x" is outside/a/x for the OS, although a lexical clean
    // would make it ws/x.
    QVERIFY(QDir().mkpath(outside() + QStringLiteral("/a/b")));
    QVERIFY(QFile::link(outside() + QStringLiteral("/a/b"), ws() + QStringLiteral("/jump")));
    const QString message =
        test::errorOf([&] { resolveInWorkspace(ws(), QStringLiteral("jump/../x.json"), what); });
    QVERIFY2(message.contains(outside() + QStringLiteral("/a/x.json")), qPrintable(message));
    // and inside: ws/in -> ws/sub/deeper, "in/../x" is ws/sub/x
    QVERIFY(QFile::link(ws() + QStringLiteral("/sub/deeper"), ws() + QStringLiteral("/in")));
    QCOMPARE(resolveInWorkspace(ws(), QStringLiteral("in/../x.json"), what),
             ws() + QStringLiteral("/sub/x.json"));
}

void TestWorkspace::workspaceGivenThroughASymlink_isAccepted()
{
    const QString alias = QDir(m_root->path()).canonicalPath() + QStringLiteral("/alias");
    QVERIFY(QFile::link(ws(), alias));
    QCOMPARE(resolveInWorkspace(alias, QStringLiteral("out.json"), what),
             ws() + QStringLiteral("/out.json"));
    QCOMPARE(resolveInWorkspace(alias, alias + QStringLiteral("/out.json"), what),
             ws() + QStringLiteral("/out.json"));
}

void TestWorkspace::missingWorkspace_isRejected()
{
    LEARNID_VERIFY_ERROR(
        resolveInWorkspace(ws() + QStringLiteral("/none"), QStringLiteral("x"), what),
        QStringLiteral("--report: the workspace"));
}

void TestWorkspace::emptyPath_isRejected()
{
    LEARNID_VERIFY_ERROR(resolveInWorkspace(ws(), QString(), what),
                         QStringLiteral("--report: no path given"));
}

QTEST_GUILESS_MAIN(TestWorkspace)
#include "tst_workspace.moc"
