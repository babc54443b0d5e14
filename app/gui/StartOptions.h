#pragma once

#include "ScreenshotRun.h"

#include <QString>

class QCoreApplication;

namespace learnid {

/// What `learnid` was started with: `--screenshot FILE [--screenshot-view VIEW]`, `--language L`,
/// and the scenario to open (`learnid SCENARIO.json` or `--scenario FILE`).
struct StartOptions
{
    QString screenshot;                                   ///< "": none
    ScreenshotRun::View view = ScreenshotRun::View::Main; ///< --screenshot-view
    QString language; ///< --language, else the remembered one (not for --screenshot); "": system
    QString scenario; ///< "": none
};

/// Parses learnid's command line on a console application, before any window: --help, --version
/// and bad options need no display. Prints help, version or the error; returns the exit code to
/// end with (0 after --help and --version, 1 after an error), or -1 to go on with *options.
/// Without a display (Linux: no DISPLAY, WAYLAND_DISPLAY or QT_QPA_PLATFORM) it says in one line
/// that the window needs one, and returns 1.
int parseStartOptions(int argc, char **argv, StartOptions *options);

/// learnid's translators for language ("": the system locale) on app; numbers and dates follow
/// the same locale.
void installLanguage(QCoreApplication &app, const QString &language);

} // namespace learnid
