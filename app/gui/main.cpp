#include "ScreenshotRun.h"
#include "StartOptions.h"
#include "ui/FileController.h"
#include "ui/MainWindow.h"

#include <QApplication>
#include <QSettings>
#include <QTemporaryDir>
#include <cstdio>
#include <memory>

namespace {

void setNames()
{
    QCoreApplication::setOrganizationName(QStringLiteral("learnid"));
    QCoreApplication::setApplicationName(QStringLiteral("learnid"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LEARNID_VERSION));
}

} // namespace

int main(int argc, char **argv)
{
    // The command line first, without a window: help, version and errors need no display.
    setNames();
    learnid::StartOptions options;
    if (const int exitCode = learnid::parseStartOptions(argc, argv, &options); exitCode >= 0)
        return exitCode;

    QApplication app(argc, argv);
    setNames();
    QApplication::setApplicationDisplayName(QStringLiteral("learnid"));
    QApplication::setDesktopFileName(QStringLiteral("learnid"));
    learnid::installLanguage(app, options.language);

    // A screenshot must not depend on (or change) the technician's remembered settings.
    QTemporaryDir scratch;
    const bool screenshot = !options.screenshot.isEmpty();
    std::unique_ptr<QSettings> settings =
        screenshot ? std::make_unique<QSettings>(scratch.filePath(QStringLiteral("learnid.ini")),
                                                 QSettings::IniFormat)
                   : std::make_unique<QSettings>();

    learnid::MainWindow window(settings.get());
    if (!options.scenario.isEmpty()) {
        // As desktop programs open the file they are given; the window says how it went, and
        // so does stderr when it failed.
        bool opened = false;
        const auto connection =
            QObject::connect(window.files(), &learnid::FileController::finished,
                             [&opened](const QString &message, bool ok) {
                                 opened = ok;
                                 if (!ok)
                                     std::fprintf(stderr, "learnid: %s\n", qPrintable(message));
                             });
        window.files()->openScenarioFrom(options.scenario);
        QObject::disconnect(connection);
        if (!opened && screenshot)
            return 1;
    }
    if (screenshot) {
        auto *run = new learnid::ScreenshotRun(&window, options.screenshot, options.view);
        run->start();
    } else {
        window.show();
    }
    return app.exec();
}
