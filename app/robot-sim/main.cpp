#include "robot-sim/SimOptions.h"
#include "robot-sim/SimProcess.h"
#include "translations/Translations.h"

#include <QCoreApplication>
#include <QLocale>
#include <QTextStream>

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("learnid-robot-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LEARNID_VERSION));
    learnid::installTranslators(app, QLocale::system()); // messages in the user's language

    QTextStream out(stdout);
    QTextStream err(stderr);
    using namespace learnid::robotsim;
    const SimCommandLine cl = parseSimCommandLine(QCoreApplication::arguments());
    switch (cl.command) {
    case SimCommandLine::Command::Help:
        out << cl.usage;
        return ExitOk;
    case SimCommandLine::Command::Version:
        out << QStringLiteral("learnid-robot-sim %1\n").arg(QStringLiteral(LEARNID_VERSION));
        return ExitOk;
    case SimCommandLine::Command::Run: {
        SimProcess process(cl.options, out, err);
        return process.run();
    }
    case SimCommandLine::Command::None:
        break;
    }
    err << QCoreApplication::translate("learnid-robot-sim", "learnid-robot-sim: error: %1")
               .arg(cl.error)
        << Qt::endl
        << QCoreApplication::translate("learnid-robot-sim",
                                       "Try 'learnid-robot-sim --help' for the options.")
        << Qt::endl;
    return ExitUsage;
}
