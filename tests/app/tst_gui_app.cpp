// The `learnid` executable as a technician starts it: --screenshot renders the main window after
// a simulated session (the README's and the user guide's pictures come from it), and bad
// options end with a clear message and a non-zero exit.
#include "../support/SharedData.h"
#include "../support/ToolRun.h"

#include <QFile>
#include <QImage>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>
#include <QtTest>

class TestGuiApp : public QObject
{
    Q_OBJECT

private:
    using Run = learnid::test::ToolRun;

    /// data: LEARNID_DATA for the recorded-data view ("": unset).
    static Run learnid(const QStringList &arguments, const QString &data = {})
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
        env.remove(QStringLiteral("LEARNID_DATA"));
        if (!data.isEmpty())
            env.insert(QStringLiteral("LEARNID_DATA"), data);
        return learnid::test::runTool(QStringLiteral(LEARNID_GUI_PATH), arguments, {}, 120000, env);
    }

    // Distinct colours in a coarse grid of the picture: a blank or failed render has a handful.
    static int distinctColours(const QImage &image)
    {
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 3)
            for (int x = 0; x < image.width(); x += 3)
                colours.insert(image.pixel(x, y));
        return int(colours.size());
    }

private slots:
    void screenshot_rendersTheWindowAfterASession_data()
    {
        QTest::addColumn<QString>("view");
        QTest::addColumn<int>("minWidth");
        QTest::newRow("main") << QStringLiteral("main") << 1000;
        QTest::newRow("apply-dialog") << QStringLiteral("apply-dialog") << 300;
        QTest::newRow("refused-check") << QStringLiteral("refused-check") << 1000;
    }

    void screenshot_rendersTheWindowAfterASession()
    {
        QFETCH(QString, view);
        QFETCH(int, minWidth);
        QTemporaryDir dir;
        const QString png = dir.filePath(view + QStringLiteral(".png"));
        const Run run = learnid(
            {QStringLiteral("--screenshot"), png, QStringLiteral("--screenshot-view"), view});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QImage image(png);
        QVERIFY2(!image.isNull(), qPrintable(png));
        QVERIFY2(image.width() >= minWidth && image.height() >= 200,
                 qPrintable(QStringLiteral("%1 x %2").arg(image.width()).arg(image.height())));
        QVERIFY2(distinctColours(image) > 40, qPrintable(QString::number(distinctColours(image))));
    }

    // docs/images/recorded-data.png: the KUKA LWR4+ identified from its recorded runs.
    void screenshot_recordedData_rendersTheIdentifiedRobot()
    {
        if (learnid::test::sharedDataFile(QStringLiteral("kuka-lwr4/measurements_3.csv")).isEmpty())
            QSKIP(qPrintable(learnid::test::sharedDataMissing()));
        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("recorded-data.png"));
        const QStringList args{QStringLiteral("--screenshot"), png,
                               QStringLiteral("--screenshot-view"),
                               QStringLiteral("recorded-data")};
        const Run run = learnid(args, learnid::test::sharedDataDir());
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        const QImage image(png);
        QVERIFY2(image.width() >= 1000 && image.height() >= 600,
                 qPrintable(QStringLiteral("%1 x %2").arg(image.width()).arg(image.height())));
        QVERIFY2(distinctColours(image) > 40, qPrintable(QString::number(distinctColours(image))));

        const Run without = learnid(args);
        QCOMPARE(without.exitCode, 1);
        QVERIFY2(without.err.contains(QStringLiteral("set LEARNID_DATA")), qPrintable(without.err));
    }

    // docs/images/payload.png: the payload step after its trials on the simulated Panda.
    void screenshot_payload_rendersTheLearnedPayload()
    {
        const QString scenario = QFINDTESTDATA("../fuzz/corpus/scenario/valid-payload.json");
        QVERIFY(!scenario.isEmpty());
        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("payload.png"));
        const QStringList args{QStringLiteral("--screenshot"), png,
                               QStringLiteral("--screenshot-view"), QStringLiteral("payload")};
        const Run run = learnid(args + QStringList{QStringLiteral("--scenario"), scenario});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        const QImage image(png);
        QVERIFY2(image.width() >= 1000 && image.height() >= 600,
                 qPrintable(QStringLiteral("%1 x %2").arg(image.width()).arg(image.height())));
        QVERIFY2(distinctColours(image) > 40, qPrintable(QString::number(distinctColours(image))));

        const Run without = learnid(args); // the window's own scenario has no payload
        QCOMPARE(without.exitCode, 1);
        QVERIFY2(without.err.contains(QStringLiteral("with a payload section")),
                 qPrintable(without.err));
    }

    void badOptions_endWithAClearMessage_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("expected");
        QTest::newRow("unknown option")
            << QStringList{QStringLiteral("--bogus")} << QStringLiteral("bogus");
        QTest::newRow("unwritable screenshot")
            << QStringList{QStringLiteral("--screenshot"), QStringLiteral("/nonexistent/x.png")}
            << QStringLiteral("learnid: --screenshot: cannot write /nonexistent/x.png");
        QTest::newRow("unknown view")
            << QStringList{QStringLiteral("--screenshot"), QStringLiteral("x.png"),
                           QStringLiteral("--screenshot-view"), QStringLiteral("bogus")}
            << QStringLiteral("learnid: unknown --screenshot-view 'bogus'; known: main, "
                              "apply-dialog, refused-check");
    }

    void badOptions_endWithAClearMessage()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, expected);
        const Run run = learnid(arguments);
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains(expected), qPrintable(run.err));
    }

    // learnid --help where there is no display (a server, an SSH session): the options, and
    // that the window needs a display; without --help one line says so, not Qt's abort.
    void help_withoutADisplay_printsTheOptions()
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char *name : {"QT_QPA_PLATFORM", "DISPLAY", "WAYLAND_DISPLAY"})
            env.remove(QLatin1String(name));
        env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
        const QString program = QStringLiteral(LEARNID_GUI_PATH);
        const Run help =
            learnid::test::runTool(program, {QStringLiteral("--help")}, {}, 60000, env);
        QVERIFY2(help.exitCode == 0, qPrintable(help.err));
        for (const char *expected :
             {"Usage:", "--screenshot <file>", "--scenario <file>", "--language <locale>",
              "[SCENARIO.json]", "The window needs a display; learnid-cli works without one."})
            QVERIFY2(help.out.contains(QLatin1String(expected)), qPrintable(help.out));
        QVERIFY2(help.err.isEmpty(), qPrintable(help.err));

        const Run window = learnid::test::runTool(program, {}, {}, 60000, env);
        QCOMPARE(window.exitCode, 1);
        QCOMPARE(window.err.trimmed().count(QLatin1Char('\n')), 0); // one line
        QVERIFY2(window.err.startsWith(QLatin1String("learnid: the window needs a display")),
                 qPrintable(window.err));
        QVERIFY2(!window.err.contains(QLatin1String("could not connect")), qPrintable(window.err));
    }

    // learnid SCENARIO.json (or --scenario FILE) opens that scenario: here one whose abort limit
    // (0.001 deg) the paper arm's first trial exceeds (0.039 deg), so the session the screenshot
    // runs does not complete, where the default scenario's does (screenshot_rendersTheWindow...).
    void scenarioArgument_opensThatScenario()
    {
        QTemporaryDir dir;
        const QString scenario = dir.filePath(QStringLiteral("aborted.json"));
        QFile file(scenario);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"estimator": {"iterations": 2}, "safety": {"maxTrackingErrorDeg": 0.001}})");
        file.close();
        const QString png = dir.filePath(QStringLiteral("x.png"));
        const QStringList screenshot{QStringLiteral("--screenshot"), png};
        for (const QStringList &given :
             {QStringList{scenario}, QStringList{QStringLiteral("--scenario"), scenario}}) {
            const Run run = learnid(given + screenshot);
            QCOMPARE(run.exitCode, 1);
            QVERIFY2(run.err.contains(QLatin1String("the simulated session did not complete")),
                     qPrintable(run.err));
        }
        const QString missing = dir.filePath(QStringLiteral("missing.json"));
        const Run notLoaded = learnid(QStringList{missing} + screenshot);
        QCOMPARE(notLoaded.exitCode, 1);
        QVERIFY2(notLoaded.err.contains(
                     QStringLiteral("Scenario not loaded: cannot read %1").arg(missing)),
                 qPrintable(notLoaded.err));
        const Run two = learnid({scenario, QStringLiteral("--scenario"), missing});
        QCOMPARE(two.exitCode, 1);
        QVERIFY2(two.err.contains(QStringLiteral("learnid: one scenario at a time, got 2")),
                 qPrintable(two.err));
    }

    void unknownLanguage_stillStartsTheWindow()
    {
        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("xx.png"));
        const Run run = learnid({QStringLiteral("--language"), QStringLiteral("xx"),
                                 QStringLiteral("--screenshot"), png});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY(!QImage(png).isNull());
    }
};

QTEST_GUILESS_MAIN(TestGuiApp)
#include "tst_gui_app.moc"
