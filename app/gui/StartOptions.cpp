#include "StartOptions.h"

#include "translations/Translations.h"
#include "ui/UiSettings.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QLocale>
#include <QSettings>
#include <cstdio>

namespace learnid {

namespace {

void printError(const QString &message)
{
    std::fprintf(stderr, "%s\n", qPrintable(message));
}

// The language the texts are shown in: --language, else the remembered one; a screenshot does
// not depend on the technician's settings. A first parse, before the translated options exist.
QString languageOf(const QStringList &arguments)
{
    QCommandLineParser first;
    const QCommandLineOption language(QStringLiteral("language"), QString(), QStringLiteral("l"));
    const QCommandLineOption screenshot(QStringLiteral("screenshot"), QString(),
                                        QStringLiteral("f"));
    first.addOptions({language, screenshot});
    (void)first.parse(arguments); // unknown options are the real parse's to report
    if (first.isSet(language))
        return first.value(language);
    if (first.isSet(screenshot))
        return {};
    QSettings settings;
    return UiSettings(&settings).language();
}

bool hasDisplay()
{
#ifdef Q_OS_LINUX
    return !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") ||
           !qEnvironmentVariableIsEmpty("DISPLAY") ||
           !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
#else
    return true;
#endif
}

} // namespace

void installLanguage(QCoreApplication &app, const QString &language)
{
    const QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    QLocale::setDefault(QLocale(locale.language(), locale.territory()));
    installTranslators(app, locale);
}

int parseStartOptions(int argc, char **argv, StartOptions *options)
{
    QCoreApplication app(argc, argv);
    options->language = languageOf(app.arguments());
    installLanguage(app, options->language);

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QCoreApplication::translate(
            "main", "Commissioning tool: learning identification of robot dynamics.") +
        QLatin1Char('\n') +
        QCoreApplication::translate("main",
                                    "The window needs a display; learnid-cli works without one."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QCoreApplication::translate(
            "main", "Run a simulated session, save the window as PNG to <file> and exit."),
        QStringLiteral("file"));
    const QCommandLineOption language(
        QStringLiteral("language"),
        QCoreApplication::translate("main",
                                    "User interface language, e.g. de or zh_CN (default: as "
                                    "chosen in the app, else the system's)."),
        QStringLiteral("locale"));
    const QCommandLineOption screenshotView(
        QStringLiteral("screenshot-view"),
        QCoreApplication::translate("main", "What --screenshot shows: %1 (default: main).")
            .arg(ScreenshotRun::viewNames().join(QStringLiteral(", "))),
        QStringLiteral("view"), QStringLiteral("main"));
    const QCommandLineOption scenario(
        QStringLiteral("scenario"),
        QCoreApplication::translate("main", "Open the scenario <file> at start."),
        QStringLiteral("file"));
    parser.addOptions({screenshot, screenshotView, language, scenario});
    parser.addPositionalArgument(
        QStringLiteral("scenario"),
        QCoreApplication::translate("main", "A scenario file to open at start (as --scenario)."),
        QStringLiteral("[SCENARIO.json]"));
    parser.process(app); // --help, --version and syntax errors end here

    const auto view = ScreenshotRun::viewNamed(parser.value(screenshotView));
    if (!view) {
        printError(QCoreApplication::translate("main",
                                               "learnid: unknown --screenshot-view '%1'; known: %2")
                       .arg(parser.value(screenshotView),
                            ScreenshotRun::viewNames().join(QStringLiteral(", "))));
        return 1;
    }
    QStringList scenarios = parser.positionalArguments();
    if (parser.isSet(scenario))
        scenarios.prepend(parser.value(scenario));
    if (scenarios.size() > 1) {
        printError(
            QCoreApplication::translate("main", "learnid: one scenario at a time, got %1: %2")
                .arg(scenarios.size())
                .arg(scenarios.join(QStringLiteral(", "))));
        return 1;
    }
    if (!hasDisplay()) {
        printError(QCoreApplication::translate(
            "main", "learnid: the window needs a display, and none is set (DISPLAY, "
                    "WAYLAND_DISPLAY); learnid --help lists the options, learnid-cli works "
                    "without a display."));
        return 1;
    }
    options->screenshot = parser.value(screenshot);
    options->view = *view;
    options->scenario = scenarios.value(0);
    return -1;
}

} // namespace learnid
