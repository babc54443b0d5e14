#include "IoTestSupport.h"
#include "io/AtomicFile.h"
#include "io/PathCsv.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>
#include <random>

using namespace learnid;
using learnid::test::bitEqual;

class TestPathCsv : public QObject
{
    Q_OBJECT

private slots:
    void roundTrip_writtenFile_readsBackBitExact();
    void commentsBlankLinesCrlfSpacesAndBom_areAccepted();
    void badInput_namesFileLineAndColumn_data();
    void badInput_namesFileLineAndColumn();
    void missingFile_namesThePath();
    void writer_refusesMismatchedSizes();

private:
    // Writes content into a fresh file of the temporary folder and returns its path.
    QString writeTemp(const QByteArray &content)
    {
        const QString path = m_dir.filePath(QStringLiteral("path-%1.csv").arg(++m_files));
        writeFileAtomically(path, content);
        return path;
    }

    QTemporaryDir m_dir;
    int m_files = 0;
};

void TestPathCsv::roundTrip_writtenFile_readsBackBitExact()
{
    QVERIFY(m_dir.isValid());
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> angle(-3.2, 3.2), step(1e-4, 3e-3);
    PathSamples written;
    written.t.resize(500);
    written.q.resize(3, 500);
    double t = 12.5;
    for (int k = 0; k < 500; ++k) {
        written.t[k] = t;
        t += step(rng);
        for (int j = 0; j < 3; ++j)
            written.q(j, k) = angle(rng);
    }
    written.q(1, 7) = 1e-300; // the shortest form must still read back exactly
    const QByteArray csv = pathCsv(written);
    QVERIFY(csv.startsWith("t,q1,q2,q3\n"));
    const PathSamples read = readPathCsvFile(writeTemp(csv), 3);
    QCOMPARE(read.dof(), 3);
    QCOMPARE(read.samples(), 500);
    QVERIFY(bitEqual(read.t, written.t));
    QVERIFY(bitEqual(read.q, written.q));
    QVERIFY(bitEqual(readPathCsvFile(writeTemp(csv)).q, written.q)); // any joint count
}

void TestPathCsv::commentsBlankLinesCrlfSpacesAndBom_areAccepted()
{
    const QByteArray csv = "\xEF\xBB\xBF# production path, cell 4\r\n"
                           "  # angles in rad\r\n"
                           "\r\n"
                           "t, q1 ,q2\r\n"
                           "0.0, 0.5, -1\r\n"
                           "0.01,0.51,-0.99\r\n"
                           "   # a pause follows\r\n"
                           "0.02,0.52,-0.98\r\n"
                           "\r\n"
                           "0.5,0.52,-0.98\r\n";
    const PathSamples path = readPathCsv(csv, QStringLiteral("cell4.csv"), 2);
    QCOMPARE(path.samples(), 4);
    QVERIFY(bitEqual(path.t, Eigen::Vector4d(0.0, 0.01, 0.02, 0.5)));
    Eigen::MatrixXd q(2, 4);
    q << 0.5, 0.51, 0.52, 0.52, -1, -0.99, -0.98, -0.98;
    QVERIFY(bitEqual(path.q, q));
}

void TestPathCsv::badInput_namesFileLineAndColumn_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<int>("expectedJoints");
    QTest::addColumn<QString>("where");
    QTest::addColumn<QString>("what");
    const QByteArray head = "t,q1,q2\n0,0.1,0.2\n";
    const QByteArray tail = "0.03,0.1,0.2\n0.04,0.1,0.2\n0.05,0.1,0.2\n";
    QTest::newRow("empty") << QByteArray() << 0 << "line 1:"
                           << "the file holds no header line; expected t,q1,...,qn";
    QTest::newRow("only comments") << QByteArray("# a\n\n# b\n") << 0 << "line 4:"
                                   << "the file holds no header line";
    QTest::newRow("header misnamed time")
        << QByteArray("time,q1\n") + tail << 0 << "line 1, column 1:"
        << "expected t, got \"time\"";
    QTest::newRow("header skips a joint")
        << QByteArray("# c\nt,q1,q3\n") + tail << 0 << "line 2, column 3:"
        << "the header must be t,q1,...,qn (the time, then one column per joint); expected q2, "
           "got \"q3\"";
    QTest::newRow("header without joints")
        << QByteArray("t\n0\n1\n2\n3\n") << 0 << "line 1, column 2:"
        << "joint columns are missing";
    QTest::newRow("data without header")
        << QByteArray("0,0.1,0.2\n") + tail << 0 << "line 1, column 1:"
        << "expected t, got \"0\"";
    QTest::newRow("too few fields") << head + "0.01,0.1\n" + tail << 0 << "line 3, column 3 (q2):"
                                    << "expected 3 fields (t,q1,q2), got 2";
    QTest::newRow("too many fields")
        << head + "0.01,0.1,0.2,0.3\n" + tail << 0 << "line 3, column 4:"
        << "expected 3 fields (t,q1,q2), got 4";
    QTest::newRow("not a number") << head + "0.01,abc,0.2\n" + tail << 0 << "line 3, column 2 (q1):"
                                  << "not a number: \"abc\"";
    QTest::newRow("semicolon") << head + "0.01,0.1,0;2\n" + tail << 0 << "line 3, column 3 (q2):"
                               << "not a number: \"0;2\"";
    QTest::newRow("empty field") << head + "0.01,,0.2\n" + tail << 0 << "line 3, column 2 (q1):"
                                 << "the field is empty; expected a number";
    QTest::newRow("nan angle") << head + "0.01,0.1,nan\n" + tail << 0 << "line 3, column 3 (q2):"
                               << "must be a finite number, got nan";
    QTest::newRow("infinite time") << head + "inf,0.1,0.2\n" + tail << 0 << "line 3, column 1 (t):"
                                   << "must be a finite number, got inf";
    QTest::newRow("out of range") << head + "0.01,1e999,0.2\n" + tail << 0
                                  << "line 3, column 2 (q1):"
                                  << "not a number: \"1e999\"";
    QTest::newRow("repeated time")
        << head + "# c\n0.01,0.1,0.2\n\n0.01,0.1,0.2\n" + tail << 0 << "line 6, column 1 (t):"
        << "the times must increase from sample to sample, got 0.01 after 0.01 on line 4";
    QTest::newRow("decreasing time")
        << head + "-0.5,0.1,0.2\n" + tail << 0 << "line 3, column 1 (t):"
        << "got -0.5 after 0 on line 2";
    QTest::newRow("three samples") << QByteArray("t,q1\n0,1\n1,2\n2,3\n") << 0 << "line 5:"
                                   << "3 samples after the header on line 1; a path needs at "
                                      "least 4";
    QTest::newRow("three samples, no final newline")
        << QByteArray("t,q1\n0,1\n1,2\n2,3") << 0 << "line 5:"
        << "3 samples";
    QTest::newRow("more joints than the robot")
        << QByteArray("t,q1,q2,q3\n") + "0,1,2,3\n1,1,2,3\n2,1,2,3\n3,1,2,3\n"
        << 2 << "line 1, column 4:"
        << "the header names the joints q1..q3; the robot has 2 joints";
    QTest::newRow("fewer joints than the robot")
        << head + tail << 3 << "line 1, column 4:"
        << "the header names the joints q1..q2; the robot has 3 joints";
}

void TestPathCsv::badInput_namesFileLineAndColumn()
{
    QFETCH(QByteArray, content);
    QFETCH(int, expectedJoints);
    QFETCH(QString, where);
    QFETCH(QString, what);
    QVERIFY(m_dir.isValid());
    const QString path = writeTemp(content);
    LEARNID_VERIFY_ERROR(readPathCsvFile(path, expectedJoints),
                         QDir::toNativeSeparators(path) + QStringLiteral(": ") + where);
    LEARNID_VERIFY_ERROR(readPathCsvFile(path, expectedJoints), what);
}

void TestPathCsv::missingFile_namesThePath()
{
    const QString path = m_dir.filePath(QStringLiteral("absent.csv"));
    LEARNID_VERIFY_ERROR(readPathCsvFile(path),
                         QStringLiteral("cannot read ") + QDir::toNativeSeparators(path));
}

void TestPathCsv::writer_refusesMismatchedSizes()
{
    PathSamples path;
    path.t = Eigen::Vector3d(0, 1, 2);
    path.q = Eigen::MatrixXd::Zero(2, 4);
    LEARNID_VERIFY_ERROR(pathCsv(path), QStringLiteral("3 sample times but 4 samples"));
}

QTEST_GUILESS_MAIN(TestPathCsv)
#include "tst_pathcsv.moc"
