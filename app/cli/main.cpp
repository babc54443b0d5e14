#include "cli/CliOptions.h"
#include "cli/IdentifyCommand.h"
#include "cli/RunCommand.h"
#include "translations/Translations.h"

#include <QCoreApplication>
#include <QLocale>
#include <QTextStream>
#include <cstdio>

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
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
        return printScenarioCommand(out);
    case CommandLine::Command::Run:
    case CommandLine::Command::Replay:
        return runCommand(cl.run, out, err);
    case CommandLine::Command::Identify:
        return identifyCommand(cl.identify, out, err);
    case CommandLine::Command::None:
        break;
    }
    err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(cl.error)
        << Qt::endl;
    if (cl.errorCode == ExitUsage)
        err << cl.usage;
    return cl.errorCode;
}
