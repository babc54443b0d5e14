#include "cli/CliOptions.h"

#include "io/Workspace.h"
#include "model/Error.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>

namespace learnid::cli {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("learnid-cli", text);
}

QString usageText()
{
    return tr("Usage:\n"
              "  learnid-cli scenario --print\n"
              "      Print the default scenario (the paper scenario) as JSON.\n"
              "  learnid-cli run [--scenario FILE] [--estimator paper|improved] [--iterations N]\n"
              "                  [--report FILE] [--export FILE] [--trial-csv DIR] [--apply]\n"
              "                  [--workspace DIR] [--quiet]\n"
              "      Run a commissioning session on the simulated robot. The table goes to\n"
              "      stdout, progress to stderr. Output paths must lie inside the workspace\n"
              "      (default: the current directory). Files are written only when every\n"
              "      trial completed.\n");
}

} // namespace

CommandLine parseCommandLine(const QStringList &args)
{
    CommandLine cl;
    cl.usage = usageText();
    const QString command = args.size() > 1 ? args.at(1) : QString();
    if (command == QLatin1String("--help") || command == QLatin1String("-h")
        || command == QLatin1String("help")) {
        cl.command = CommandLine::Command::Help;
        return cl;
    }
    if (command == QLatin1String("--version")) {
        cl.command = CommandLine::Command::Version;
        return cl;
    }

    QCommandLineParser parser;
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption print(QStringLiteral("print"), tr("Print the default scenario."));
    const QCommandLineOption scenario(QStringLiteral("scenario"), tr("Scenario file."),
                                      QStringLiteral("FILE"));
    const QCommandLineOption estimator(QStringLiteral("estimator"), tr("Learning law."),
                                       QStringLiteral("LAW"));
    const QCommandLineOption iterations(QStringLiteral("iterations"), tr("Learning trials."),
                                        QStringLiteral("N"));
    const QCommandLineOption report(QStringLiteral("report"), tr("JSON report."),
                                    QStringLiteral("FILE"));
    const QCommandLineOption exportFile(QStringLiteral("export"), tr("Parameter file."),
                                        QStringLiteral("FILE"));
    const QCommandLineOption trialCsv(QStringLiteral("trial-csv"), tr("Trial CSV folder."),
                                      QStringLiteral("DIR"));
    const QCommandLineOption apply(QStringLiteral("apply"), tr("Apply the final estimate."));
    const QCommandLineOption workspace(QStringLiteral("workspace"), tr("Workspace folder."),
                                       QStringLiteral("DIR"));
    const QCommandLineOption quiet(QStringLiteral("quiet"), tr("No progress on stderr."));

    if (command == QLatin1String("scenario")) {
        parser.addOption(print);
        if (!parser.parse(args.mid(1))) {
            cl.error = parser.errorText();
        } else if (!parser.isSet(print) || !parser.positionalArguments().isEmpty()) {
            cl.error = tr("'scenario' needs --print");
        } else {
            cl.command = CommandLine::Command::PrintScenario;
        }
        return cl;
    }
    if (command != QLatin1String("run")) {
        cl.error = command.isEmpty() ? tr("no command given")
                                     : tr("unknown command '%1'").arg(command);
        return cl;
    }

    parser.addOptions(
        {scenario, estimator, iterations, report, exportFile, trialCsv, apply, workspace, quiet});
    if (!parser.parse(args.mid(1))) {
        cl.error = parser.errorText();
        return cl;
    }
    if (!parser.positionalArguments().isEmpty()) {
        cl.error = tr("unexpected argument '%1'").arg(parser.positionalArguments().first());
        return cl;
    }
    RunOptions &run = cl.run;
    run.scenarioPath = parser.value(scenario);
    if (parser.isSet(estimator))
        run.law = parser.value(estimator);
    if (parser.isSet(iterations)) {
        bool ok = false;
        const int n = parser.value(iterations).toInt(&ok);
        if (!ok || n < 1 || n > 100) {
            cl.error = tr("--iterations: must be a whole number from 1 to 100, got '%1'")
                           .arg(parser.value(iterations));
            cl.errorCode = ExitBadInput;
            return cl;
        }
        run.iterations = n;
    }
    run.apply = parser.isSet(apply);
    run.quiet = parser.isSet(quiet);
    const QString ws = parser.isSet(workspace) ? parser.value(workspace) : QDir::currentPath();
    try {
        if (parser.isSet(report))
            run.reportPath = resolveInWorkspace(ws, parser.value(report), QStringLiteral("--report"));
        if (parser.isSet(exportFile))
            run.exportPath =
                resolveInWorkspace(ws, parser.value(exportFile), QStringLiteral("--export"));
        if (parser.isSet(trialCsv))
            run.trialCsvDir =
                resolveInWorkspace(ws, parser.value(trialCsv), QStringLiteral("--trial-csv"));
    } catch (const Error &e) {
        cl.error = e.message();
        cl.errorCode = ExitBadInput;
        return cl;
    }
    cl.command = CommandLine::Command::Run;
    return cl;
}

} // namespace learnid::cli
