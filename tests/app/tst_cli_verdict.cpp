// `learnid-cli identify` prints a verdict per link on the identified parameters (and its PDF
// report holds the same text): on the KUKA LWR4+'s recorded runs, each printed row against
// checkConsistency() and checkPlausibility() of the standard parameters the tool exported; the
// wording of undetermined standard parameters; the URDF's own problems (FloBaRoID's identified
// URDF as the prior) wrapped so that no line is cut.
#include "../support/SharedData.h"
#include "../support/ToolRun.h"
#include "io/ParameterFile.h"
#include "model/CadPrior.h"
#include "model/ChainModel.h"
#include "model/PhysicalConsistency.h"
#include "model/Plausibility.h"
#include "model/UrdfChain.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

namespace {

// The rows under the verdict table's header ("link  I1 [kg m^2] ..."), split at runs of two or
// more spaces.
QList<QStringList> verdictRows(const QString &out)
{
    static const QRegularExpression gap(QStringLiteral("\\s{2,}"));
    QList<QStringList> rows;
    bool inTable = false;
    for (const QString &line : out.split(QLatin1Char('\n'))) {
        if (line.startsWith(QLatin1String("link ")) && line.contains(QLatin1String("plausible"))) {
            inTable = true;
            continue;
        }
        if (inTable && line.trimmed().isEmpty())
            break;
        if (inTable)
            rows << line.split(gap, Qt::SkipEmptyParts);
    }
    return rows;
}

// `learnid-cli identify --quiet` with args, run in dir.
test::ToolRun identify(const QStringList &args, const QString &dir)
{
    return test::runTool(QStringLiteral(LEARNID_CLI_PATH),
                         QStringList{QStringLiteral("identify"), QStringLiteral("--quiet")} + args,
                         dir);
}

QString yesNo(bool yes)
{
    return yes ? QStringLiteral("yes") : QStringLiteral("no");
}

} // namespace

class TestCliVerdict : public QObject
{
    Q_OBJECT

private slots:
    void kuka_verdictRowsAreTheLibrarysOfTheExportedParameters();
    void implausiblePrior_warningsWrappedAndEveryLinkJudged();
    void negativeFrictionPrior_warnedNotRefused_exportHasNone();
};

void TestCliVerdict::kuka_verdictRowsAreTheLibrarysOfTheExportedParameters()
{
    const QString urdf = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    const QString run1 = test::sharedDataFile(QStringLiteral("kuka-lwr4/measurements_1.csv"));
    const QString run3 = test::sharedDataFile(QStringLiteral("kuka-lwr4/measurements_3.csv"));
    if (urdf.isEmpty() || run1.isEmpty() || run3.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    QTemporaryDir dir;
    const test::ToolRun r = identify({QStringLiteral("--robot"), urdf, QStringLiteral("--log"),
                                      run3, QStringLiteral("--validate"), run1,
                                      QStringLiteral("--export"), QStringLiteral("lwr.json")},
                                     dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));

    // The verdict of the library on what the tool exported (the fit's standard parameters,
    // written to read back to the same doubles).
    const ParameterFileContent params = readParameterFile(dir.filePath(QStringLiteral("lwr.json")));
    const SerialChain chain = readUrdfChain(urdf);
    const ChainModel model(chain, JointTerms{false, true, true, true}, QStringLiteral("urdf"));
    const Eigen::VectorXd prior = realBodyPrior(model.cadStandard(), 7);
    const std::vector<LinkConsistency> consistency =
        checkConsistency(params.standardValues, 7, 1e-12);
    const std::vector<LinkPlausibility> plausibility =
        checkPlausibility(params.standardValues, prior, 7, linkVolumes(model.chain(), prior));

    const QList<QStringList> rows = verdictRows(r.out);
    QCOMPARE(rows.size(), 7);
    bool all = true;
    for (int l = 0; l < 7; ++l) {
        const LinkPlausibility &p = plausibility[size_t(l)];
        const bool consistent = consistency[size_t(l)].consistent;
        QCOMPARE(rows[l],
                 (QStringList{QStringLiteral("%1 %2").arg(l + 1).arg(chain.joints[size_t(l)].link),
                              QString::number(p.moments[0], 'g', 3),
                              QString::number(p.cadSmallestMoment, 'g', 3),
                              QString::number(p.triangleRatio, 'f', 3),
                              p.hasVolume ? yesNo(p.volumeOk) : QStringLiteral("-"),
                              yesNo(consistent), yesNo(consistent && p.plausible)}));
        all = all && consistent && p.plausible;
    }
    // The geometric prior keeps every link of the KUKA fit a plausible body (issue 22), and the
    // sentence above the tables says so.
    QVERIFY2(all, qPrintable(r.out));
    QVERIFY2(r.out.contains(QLatin1String("Identified parameters: physically consistent and "
                                          "plausible")),
             qPrintable(r.out));

    // Undetermined standard parameters are named for what they are: near the prior, not at it.
    int undetermined = 0;
    for (const QString &line : r.out.split(QLatin1Char('\n'))) {
        QVERIFY2(!line.endsWith(QLatin1String(" prior")) || line.contains(QLatin1String("kept")),
                 qPrintable(line));
        undetermined += line.endsWith(QLatin1String("undetermined (kept near the prior)"));
    }
    int below = 0;
    for (const double share : params.standardDetermined)
        below += share < 0.5;
    QCOMPARE(undetermined, below);
}

void TestCliVerdict::implausiblePrior_warningsWrappedAndEveryLinkJudged()
{
    const QString urdf = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    const QString run3 = test::sharedDataFile(QStringLiteral("kuka-lwr4/measurements_3.csv"));
    if (urdf.isEmpty() || run3.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    // The KUKA URDF with links 3 and 4 flat plates: Izz = Ixx - Iyy, so I1 + I2 = I3 (the
    // triangle rule's ratio 1, below 1.02): two warnings of about 170 characters.
    QFile in(urdf);
    QVERIFY(in.open(QIODevice::ReadOnly));
    QByteArray text = in.readAll();
    const QByteArray solid = R"(ixx="0.01845" ixy="0" ixz="0" iyy="0.00405" iyz="0" izz="0.01602")";
    const QByteArray plate = R"(ixx="0.01845" ixy="0" ixz="0" iyy="0.00405" iyz="0" izz="0.0144")";
    for (const char *link : {"<link name=\"lwr_3_link\">", "<link name=\"lwr_4_link\">"}) {
        const qsizetype at = text.indexOf(solid, text.indexOf(link));
        QVERIFY(at > 0);
        text.replace(at, solid.size(), plate);
    }
    QTemporaryDir dir;
    QFile out(dir.filePath(QStringLiteral("plates.urdf")));
    QVERIFY(out.open(QIODevice::WriteOnly) && out.write(text) == text.size());
    out.close();

    const test::ToolRun r =
        identify({QStringLiteral("--robot"), out.fileName(), QStringLiteral("--log"), run3,
                  QStringLiteral("--report"), QStringLiteral("report.pdf")},
                 dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    // Each problem a warning, its sentence wrapped at 100 characters with the continuation
    // indented (the PDF report prints the same lines), nothing of it lost.
    const QStringList lines = r.out.split(QLatin1Char('\n'));
    QStringList warnings;
    for (int i = 0; i < lines.size(); ++i) {
        if (lines[i].startsWith(QLatin1String("warning: the URDF as a real robot: "))) {
            QString sentence = lines[i];
            QVERIFY2(lines[i].size() <= 100, qPrintable(lines[i]));
            while (lines.value(i + 1).startsWith(QLatin1String("  "))) {
                QVERIFY2(lines[++i].size() <= 100, qPrintable(lines[i]));
                sentence += QLatin1Char(' ') + lines[i].trimmed();
            }
            warnings << sentence;
        }
    }
    QCOMPARE(warnings.size(), 2);
    QCOMPARE(warnings[0], QStringLiteral("warning: the URDF as a real robot: link 3 (lwr_3_link): "
                                         "its principal moments 0.00405, 0.0144 and 0.0185 kg "
                                         "m^2 give I1 + I2 = 1.000 I3, below 1.020 I3 (a flat "
                                         "plate at best)"));
    QCOMPARE(verdictRows(r.out).size(), 7);
    QVERIFY(QFile::exists(dir.filePath(QStringLiteral("report.pdf"))));
}

// FloBaRoID's identified URDF as the prior: links that are no real bodies and four negative
// <dynamics friction> values. A prior is warned about, not refused (issue 22, part 5); the fit
// starts from its nearest real bodies and frictions (realBodyPrior: a negative friction at 0)
// and writes no negative friction.
void TestCliVerdict::negativeFrictionPrior_warnedNotRefused_exportHasNone()
{
    const QString urdf =
        test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4_identified.urdf"));
    const QString run3 = test::sharedDataFile(QStringLiteral("kuka-lwr4/measurements_3.csv"));
    if (urdf.isEmpty() || run3.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    QTemporaryDir dir;
    const test::ToolRun r = identify({QStringLiteral("--robot"), urdf, QStringLiteral("--log"),
                                      run3, QStringLiteral("--export"), QStringLiteral("flo.json")},
                                     dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const SerialChain chain = readUrdfChain(urdf);
    int negative = 0;
    for (const ChainJoint &j : chain.joints) {
        if (j.friction < 0.0) {
            ++negative;
            QVERIFY2(r.out.contains(QStringLiteral("(%1): <dynamics friction> is").arg(j.name)),
                     qPrintable(r.out));
        }
    }
    QVERIFY(negative > 0);
    const ParameterFileContent params = readParameterFile(dir.filePath(QStringLiteral("flo.json")));
    const ChainModel model(chain, JointTerms{false, true, true, true}, QStringLiteral("urdf"));
    QCOMPARE(params.standardValues.size(), Eigen::Index(model.standardCount()));
    for (const int i : model.nonnegativeStandard())
        QVERIFY2(params.standardValues[i] >= 0.0,
                 qPrintable(QStringLiteral("%1 = %2")
                                .arg(model.standardParameters()[i].name)
                                .arg(params.standardValues[i])));
    QCOMPARE(verdictRows(r.out).size(), 7);
}

QTEST_GUILESS_MAIN(TestCliVerdict)
#include "tst_cli_verdict.moc"
