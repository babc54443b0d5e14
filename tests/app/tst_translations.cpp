// The translations: every text of core/, ui/ and app/ has a German and a Chinese translation, the
// core's messages reach the user translated, and the command-line tools speak the user's language.
#include "can/SdoAbortCode.h"
#include "io/ScenarioFile.h"
#include "model/Error.h"
#include "translations/Translations.h"

#include <QCoreApplication>
#include <QFile>
#include <QLocale>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QXmlStreamReader>

class TestTranslations : public QObject
{
    Q_OBJECT

private slots:
    void cleanup();
    void scenarioValidationError_comesOutInGerman();
    void sdoAbortCode_comesOutInGermanAndChinese();
    void installTranslators_findsGermanAndChineseOnly_data();
    void installTranslators_findsGermanAndChineseOnly();
    void tsFile_everyMessageFinishedWithItsPlaceholders_data();
    void tsFile_everyMessageFinishedWithItsPlaceholders();
    void tsFiles_holdTheSameTexts();
    void tsFile_holdsExactlyTheTextsOfTheSources();
    void pluralsFile_givesEveryPluralTextItsEnglishForms();
    void installTranslators_englishPluralsUnderEveryLanguage_data();
    void installTranslators_englishPluralsUnderEveryLanguage();
    void commandLineTools_speakTheSystemLanguage_data();
    void commandLineTools_speakTheSystemLanguage();

private:
    struct TsMessage
    {
        QString context;
        QString source;
        QString type;             ///< the translation's type attribute: "" when finished
        QStringList translations; ///< one, or the numerus forms
        bool numerus = false;     ///< a text with %n and plural forms
    };
    static QList<TsMessage> readTs(const QString &path, QString *error);
    static bool installFromResource(const QString &qm);
    static QString scenarioError(const QByteArray &json);
};

namespace {

// %1 ... %99 and %n (plural count); %L1 is %1 in the user's number format.
QSet<QString> placeholders(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("%L?(\\d{1,2}|n)"));
    QSet<QString> found;
    for (const QRegularExpressionMatch &m : re.globalMatch(text))
        found.insert(m.captured(1));
    return found;
}

QString tsPath(const QString &language)
{
    return QStringLiteral(LEARNID_TS_DIR "/learnid_%1.ts").arg(language);
}

} // namespace

void TestTranslations::cleanup()
{
    // A translator removes itself from the application when it is destroyed.
    qDeleteAll(qApp->findChildren<QTranslator *>());
}

bool TestTranslations::installFromResource(const QString &qm)
{
    auto *translator = new QTranslator(qApp);
    return translator->load(qm) && QCoreApplication::installTranslator(translator);
}

QString TestTranslations::scenarioError(const QByteArray &json)
{
    try {
        learnid::scenarioFromJson(json, QStringLiteral("scenario.json"));
    } catch (const learnid::Error &e) {
        return e.message();
    }
    return {};
}

void TestTranslations::scenarioValidationError_comesOutInGerman()
{
    const QByteArray json = R"({"controller": {"kp": [-5, 100]}})";
    const QString english = scenarioError(json);
    QVERIFY2(english.contains(QLatin1String("must be a positive number, got -5")),
             qPrintable(english));

    QVERIFY(installFromResource(QStringLiteral(":/i18n/learnid_de.qm")));
    const QString german = scenarioError(json);
    // The key path stays as it is in the file; the problem is told in German.
    QVERIFY2(german.startsWith(QLatin1String("scenario.json: controller.kp")), qPrintable(german));
    QVERIFY2(german.endsWith(QLatin1String("muss eine positive Zahl sein, gefunden: -5")),
             qPrintable(german));
}

void TestTranslations::sdoAbortCode_comesOutInGermanAndChinese()
{
    using namespace learnid;
    QCOMPARE(sdoabort::message(sdoabort::subIndexDoesNotExist),
             QStringLiteral("Sub-index does not exist."));
    QVERIFY(installFromResource(QStringLiteral(":/i18n/learnid_de.qm")));
    QCOMPARE(sdoabort::message(sdoabort::subIndexDoesNotExist),
             QStringLiteral("Subindex existiert nicht."));
    QCOMPARE(sdoabort::message(0x12345678), QStringLiteral("Unbekannter Abbruchcode 0x12345678."));
    cleanup();
    QVERIFY(installFromResource(QStringLiteral(":/i18n/learnid_zh_CN.qm")));
    QCOMPARE(sdoabort::message(sdoabort::subIndexDoesNotExist), QStringLiteral("子索引不存在。"));
}

void TestTranslations::installTranslators_findsGermanAndChineseOnly_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<bool>("found");
    QTest::addColumn<QString>("noObjectText"); // sdoabort::objectDoesNotExist

    QTest::newRow("de_DE") << "de_DE" << true << "Objekt existiert nicht im Objektverzeichnis.";
    QTest::newRow("de_AT") << "de_AT" << true << "Objekt existiert nicht im Objektverzeichnis.";
    QTest::newRow("zh_CN") << "zh_CN" << true << "对象字典中不存在该对象。";
    QTest::newRow("fr_FR") << "fr_FR" << false << "Object does not exist in the object dictionary.";
}

void TestTranslations::installTranslators_findsGermanAndChineseOnly()
{
    QFETCH(QString, locale);
    QFETCH(bool, found);
    QFETCH(QString, noObjectText);
    QCOMPARE(learnid::installTranslators(*QCoreApplication::instance(), QLocale(locale)), found);
    QCOMPARE(learnid::sdoabort::message(learnid::sdoabort::objectDoesNotExist), noObjectText);
}

QList<TestTranslations::TsMessage> TestTranslations::readTs(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = file.errorString();
        return {};
    }
    QList<TsMessage> messages;
    QString context;
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        const auto name = xml.name();
        if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            messages.append(
                {context,
                 {},
                 {},
                 {},
                 xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes")});
        } else if (name == QLatin1String("source") && !messages.isEmpty()) {
            messages.last().source = xml.readElementText();
        } else if (name == QLatin1String("translation") && !messages.isEmpty()) {
            TsMessage &m = messages.last();
            m.type = xml.attributes().value(QLatin1String("type")).toString();
            // Its text, or one <numerusform> per plural form.
            QString text;
            while (xml.readNext() != QXmlStreamReader::EndElement && !xml.atEnd()) {
                if (xml.isCharacters())
                    text += xml.text();
                else if (xml.isStartElement())
                    m.translations << xml.readElementText();
            }
            if (m.translations.isEmpty() && !text.isEmpty())
                m.translations << text;
        }
    }
    if (xml.hasError())
        *error = QStringLiteral("line %1: %2").arg(xml.lineNumber()).arg(xml.errorString());
    return messages;
}

void TestTranslations::tsFile_everyMessageFinishedWithItsPlaceholders_data()
{
    QTest::addColumn<QString>("path");
    QTest::newRow("German") << tsPath(QStringLiteral("de"));
    QTest::newRow("Chinese") << tsPath(QStringLiteral("zh_CN"));
}

void TestTranslations::tsFile_everyMessageFinishedWithItsPlaceholders()
{
    QFETCH(QString, path);
    QString error;
    const QList<TsMessage> messages = readTs(path, &error);
    QVERIFY2(error.isEmpty(), qPrintable(path + QLatin1String(": ") + error));
    // core/, ui/ and app/ together hold several hundred texts; a handful means a broken scan.
    QVERIFY2(messages.size() > 500, qPrintable(QString::number(messages.size())));

    QStringList problems;
    for (const TsMessage &m : messages) {
        const QString where = QStringLiteral("%1: \"%2\"").arg(m.context, m.source.left(60));
        if (!m.type.isEmpty() || m.translations.isEmpty()) {
            problems << where + QStringLiteral(": not translated (%1)").arg(m.type);
            continue;
        }
        for (const QString &t : m.translations) {
            if (placeholders(t) != placeholders(m.source))
                problems << where + QStringLiteral(": placeholders differ in \"%1\"").arg(t);
        }
    }
    // Translate in Qt Linguist after running the update_translations target (README.md).
    QVERIFY2(problems.isEmpty(),
             qPrintable(QStringLiteral("%1 of %2 messages in %3:\n  %4")
                            .arg(problems.size())
                            .arg(messages.size())
                            .arg(path, problems.mid(0, 40).join(QStringLiteral("\n  ")))));
}

void TestTranslations::tsFiles_holdTheSameTexts()
{
    QString error;
    QSet<QString> german, chinese;
    for (const TsMessage &m : readTs(tsPath(QStringLiteral("de")), &error))
        german.insert(m.context + QLatin1Char('\x1f') + m.source);
    for (const TsMessage &m : readTs(tsPath(QStringLiteral("zh_CN")), &error))
        chinese.insert(m.context + QLatin1Char('\x1f') + m.source);
    QVERIFY(error.isEmpty());
    QCOMPARE(german, chinese);
}

void TestTranslations::tsFile_holdsExactlyTheTextsOfTheSources()
{
    // lupdate over today's sources, as `update_translations` runs it: a text added to the code
    // without running update_translations (and translating it) would show in English.
    QTemporaryDir dir;
    const QString fresh = dir.filePath(QStringLiteral("fresh.ts"));
    const QString root = QStringLiteral(LEARNID_SOURCE_DIR);
    QProcess lupdate;
    lupdate.start(QStringLiteral(LEARNID_LUPDATE),
                  {QStringLiteral("-silent"), QStringLiteral("-locations"), QStringLiteral("none"),
                   QStringLiteral("-I"), root, QStringLiteral("-I"), root + QStringLiteral("/core"),
                   QStringLiteral("-I"), root + QStringLiteral("/app"),
                   QLatin1Char('@') + QStringLiteral(LEARNID_SOURCE_LIST), QStringLiteral("-ts"),
                   fresh});
    QVERIFY(lupdate.waitForFinished(120000));
    const QString warnings = QString::fromLocal8Bit(lupdate.readAllStandardError());
    QVERIFY2(lupdate.exitCode() == 0, qPrintable(warnings));
    // A tr() lupdate cannot tie to a context (a file-local helper, a class without Q_OBJECT or
    // Q_DECLARE_TR_FUNCTIONS) files its text under a context the code never looks up.
    QVERIFY2(!warnings.contains(QLatin1String("lacks Q_OBJECT")), qPrintable(warnings));
    QString error;
    const QList<TsMessage> found = readTs(fresh, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY(found.size() > 100);
    // By context and source text, as a translation is looked up at run time.
    const auto key = [](const TsMessage &m) {
        return m.context + QLatin1String(": ") + m.source;
    };
    QSet<QString> inSources, inTs;
    for (const TsMessage &m : found)
        inSources.insert(key(m));
    for (const TsMessage &m : readTs(tsPath(QStringLiteral("de")), &error))
        inTs.insert(key(m));
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QStringList missing = (inSources - inTs).values();
    QStringList stale = (inTs - inSources).values();
    missing.sort();
    stale.sort();
    QVERIFY2(missing.isEmpty(),
             qPrintable(QStringLiteral("not in translations/*.ts (run the update_translations "
                                       "target and translate): ") +
                        missing.join(QStringLiteral(" | "))));
    QVERIFY2(stale.isEmpty(),
             qPrintable(QStringLiteral("in translations/*.ts but no longer in the sources (run "
                                       "the update_translations target): ") +
                        stale.join(QStringLiteral(" | "))));
}

void TestTranslations::pluralsFile_givesEveryPluralTextItsEnglishForms()
{
    // English needs a translation for its plurals only ("1 log", "2 logs"): every text with %n
    // of the German file, and nothing else, with two finished forms and their placeholders.
    QString error;
    QSet<QString> plurals, english;
    for (const TsMessage &m : readTs(tsPath(QStringLiteral("de")), &error)) {
        if (m.numerus)
            plurals.insert(m.context + QLatin1String(": ") + m.source);
    }
    const QList<TsMessage> messages = readTs(tsPath(QStringLiteral("plurals_en")), &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QStringList problems;
    for (const TsMessage &m : messages) {
        english.insert(m.context + QLatin1String(": ") + m.source);
        const bool finished = m.type.isEmpty() && m.numerus && m.translations.size() == 2;
        if (!finished)
            problems << m.source + QStringLiteral(": not two finished forms");
        for (const QString &t : m.translations) {
            if (placeholders(t) != placeholders(m.source))
                problems << m.source + QStringLiteral(": placeholders differ in \"%1\"").arg(t);
        }
    }
    QVERIFY(plurals.size() >= 10);
    QCOMPARE(english, plurals);
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QStringLiteral("\n  "))));
}

void TestTranslations::installTranslators_englishPluralsUnderEveryLanguage_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<QString>("one");
    QTest::addColumn<QString>("two");
    QTest::newRow("C") << "C"
                       << "Fitted to 1 log, %1 samples; %2."
                       << "Fitted to 2 logs, %1 samples; %2.";
    QTest::newRow("en_US") << "en_US"
                           << "Fitted to 1 log, %1 samples; %2."
                           << "Fitted to 2 logs, %1 samples; %2.";
    QTest::newRow("fr_FR") << "fr_FR"
                           << "Fitted to 1 log, %1 samples; %2."
                           << "Fitted to 2 logs, %1 samples; %2.";
    QTest::newRow("de_DE") << "de_DE"
                           << "An 1 Log angepasst, %1 Abtastwerte; %2."
                           << "An 2 Logs angepasst, %1 Abtastwerte; %2.";
}

void TestTranslations::installTranslators_englishPluralsUnderEveryLanguage()
{
    QFETCH(QString, locale);
    QFETCH(QString, one);
    QFETCH(QString, two);
    const char *text = "Fitted to %n log(s), %1 samples; %2.";
    QCOMPARE(QCoreApplication::translate("LogIdentificationSummary", text, nullptr, 1),
             QStringLiteral("Fitted to 1 log(s), %1 samples; %2.")); // no translator: as written
    learnid::installTranslators(*QCoreApplication::instance(), QLocale(locale));
    QCOMPARE(QCoreApplication::translate("LogIdentificationSummary", text, nullptr, 1), one);
    QCOMPARE(QCoreApplication::translate("LogIdentificationSummary", text, nullptr, 2), two);
}

void TestTranslations::commandLineTools_speakTheSystemLanguage_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("lang");
    QTest::addColumn<QString>("expected"); // the start of stderr

    const QStringList unknown{QStringLiteral("no-such-command")};
    const QString cli = QStringLiteral(LEARNID_CLI_PATH);
    QTest::newRow("cli C") << cli << unknown << "C"
                           << "learnid-cli: error: unknown command 'no-such-command'";
    QTest::newRow("cli de") << cli << unknown << "de_DE.UTF-8"
                            << "learnid-cli: Fehler: unbekannter Befehl 'no-such-command'";
    QTest::newRow("cli zh_CN") << cli << unknown << "zh_CN.UTF-8"
                               << "learnid-cli：错误：未知命令 'no-such-command'";
#ifdef LEARNID_ROBOT_SIM_PATH
    const QStringList noPlugin{QStringLiteral("--can-interface"), QStringLiteral("can0")};
    const QString sim = QStringLiteral(LEARNID_ROBOT_SIM_PATH);
    QTest::newRow("robot-sim C") << sim << noPlugin << "C"
                                 << "learnid-robot-sim: error: --can-plugin is required";
    QTest::newRow("robot-sim de") << sim << noPlugin << "de_DE.UTF-8"
                                  << "learnid-robot-sim: Fehler: --can-plugin ist erforderlich";
#endif
}

void TestTranslations::commandLineTools_speakTheSystemLanguage()
{
    QFETCH(QString, program);
    QFETCH(QStringList, arguments);
    QFETCH(QString, lang);
    QFETCH(QString, expected);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"})
        env.remove(QString::fromLatin1(name));
    env.insert(QStringLiteral("LANG"), lang);
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(program, arguments);
    QVERIFY2(p.waitForFinished(30000), qPrintable(program));
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QVERIFY(p.exitCode() != 0);
    const QString err = QString::fromUtf8(p.readAllStandardError());
    QVERIFY2(err.startsWith(expected), qPrintable(err));
}

QTEST_GUILESS_MAIN(TestTranslations)
#include "tst_translations.moc"
