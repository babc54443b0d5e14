#include "cli/CliOptions.h"
#include "cli/IdentifyCommand.h"
#include "cli/LoopCommands.h"
#include "cli/RunCommand.h"
#include "cli/ScenarioCommand.h"
#include "cli/TorquePlotPng.h"
#include "translations/Translations.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QLocale>
#include <QTextStream>
#include <cstdio>
#include <memory>

int main(int argc, char **argv)
{
    // identify --plots / --report draw images, which needs Qt's GUI library (fonts); every
    // other command stays a plain console program.
    const std::unique_ptr<QCoreApplication> application =
        learnid::cli::imagesWanted(argc, argv) ? std::make_unique<QGuiApplication>(argc, argv)
                                               : std::make_unique<QCoreApplication>(argc, argv);
    QCoreApplication &app = *application;
    QCoreApplication::setApplicationName(QStringLiteral("learnid-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LEARNID_VERSION));
    learnid::installTranslators(app, QLocale::system()); // messages in the user's language

    QTextStream out(stdout);
    QTextStream err(stderr);
    using namespace learnid::cli;
    const CommandLine cl = parseCommandLine(QCoreApplication::arguments());
    switch (cl.command) {
    case CommandLine::Command::Help:
        out << cl.usage;
        return ExitOk;
    case CommandLine::Command::Version:
        out << QStringLiteral("learnid-cli %1\n").arg(QStringLiteral(LEARNID_VERSION));
        return ExitOk;
    case CommandLine::Command::PrintScenario:
        return printScenarioCommand(cl.scenarioRobot, cl.scenarioPayload, cl.scenarioSamplePeriod,
                                    out, err);
    case CommandLine::Command::Run:
    case CommandLine::Command::Replay:
        return runCommand(cl.run, out, err);
    case CommandLine::Command::Identify:
        return identifyCommand(cl.identify, out, err);
    case CommandLine::Command::Plan:
        return planCommand(cl.loop, out, err);
    case CommandLine::Command::Learn:
        return learnCommand(cl.loop, out, err);
    case CommandLine::Command::None:
        break;
    }
    err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(cl.error)
        << Qt::endl;
    if (cl.errorCode == ExitUsage)
        err << cl.usage;
    return cl.errorCode;
}
