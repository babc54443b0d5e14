// The `learnid` executable as a technician starts it: --screenshot renders the main window after
// a simulated session (the README's and the user guide's pictures come from it), and bad
// options end with a clear message and a non-zero exit.
#include "../support/SharedData.h"
#include "../support/ToolRun.h"

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
