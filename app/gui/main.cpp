#include "ScreenshotRun.h"
#include "translations/Translations.h"
#include "ui/MainWindow.h"
#include "ui/UiLogging.h"
#include "ui/UiSettings.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QLocale>
#include <QSettings>
#include <QTemporaryDir>
#include <cstdio>
#include <memory>

namespace {

// learnid's and Qt's translators for the chosen language ("" = system locale); numbers and dates
// follow the same locale.
void installTranslators(QApplication &app, const QString &language)
{
    const QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    QLocale::setDefault(QLocale(locale.language(), locale.territory()));
    learnid::installTranslators(app, locale);
}

} // namespace

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("learnid"));
    QApplication::setApplicationName(QStringLiteral("learnid"));
    QApplication::setApplicationDisplayName(QStringLiteral("learnid"));
    QApplication::setApplicationVersion(QStringLiteral(LEARNID_VERSION));
    QApplication::setDesktopFileName(QStringLiteral("learnid"));

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate(
        "main", "Commissioning tool: learning identification of robot dynamics."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QApplication::translate(
            "main", "Run a simulated session, save the window as PNG to <file> and exit."),
        QStringLiteral("file"));
    const QCommandLineOption language(
        QStringLiteral("language"),
        QApplication::translate("main", "User interface language, e.g. de or zh_CN (default: as "
                                        "chosen in the app, else the system's)."),
        QStringLiteral("locale"));
    const QCommandLineOption screenshotView(
        QStringLiteral("screenshot-view"),
        QApplication::translate("main", "What --screenshot shows: %1 (default: main).")
            .arg(learnid::ScreenshotRun::viewNames().join(QStringLiteral(", "))),
        QStringLiteral("view"), QStringLiteral("main"));
    parser.addOptions({screenshot, screenshotView, language});
    parser.process(app);
    const auto view = learnid::ScreenshotRun::viewNamed(parser.value(screenshotView));
    if (!view) {
        const QString known = learnid::ScreenshotRun::viewNames().join(QStringLiteral(", "));
        const QString error =
            QApplication::translate("main", "learnid: unknown --screenshot-view '%1'; known: %2");
        std::fprintf(stderr, "%s\n", qPrintable(error.arg(parser.value(screenshotView), known)));
        return 1;
    }

    // A screenshot must not depend on (or change) the technician's remembered settings.
    QTemporaryDir scratch;
    std::unique_ptr<QSettings> settings =
        parser.isSet(screenshot)
            ? std::make_unique<QSettings>(scratch.filePath(QStringLiteral("learnid.ini")),
                                          QSettings::IniFormat)
            : std::make_unique<QSettings>();
    const QString lang = parser.isSet(language) ? parser.value(language)
                                                : learnid::UiSettings(settings.get()).language();
    installTranslators(app, lang);

    learnid::MainWindow window(settings.get());
    if (parser.isSet(screenshot)) {
        auto *run = new learnid::ScreenshotRun(&window, parser.value(screenshot), *view);
        run->start();
    } else {
        window.show();
    }
    return app.exec();
}
