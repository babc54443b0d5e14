#include "ui/UiSettings.h"

#include "io/ScenarioFile.h"
#include "model/Error.h"
#include "ui/UiLogging.h"

#include <QDir>
#include <QSettings>

namespace learnid {

namespace {
const QString kScenario = QStringLiteral("setup/scenario");
const QString kGeometry = QStringLiteral("window/geometry");
const QString kState = QStringLiteral("window/state");
const QString kLanguage = QStringLiteral("ui/language");
const QString kAutoScale = QStringLiteral("plot/autoScale");
const QString kLastDir = QStringLiteral("files/lastDirectory");
} // namespace

UiSettings::UiSettings(QSettings *settings)
    : m_settings(settings)
{}

Scenario UiSettings::defaultScenario()
{
    try {
        return readScenarioFile(QStringLiteral(":/scenarios/paper.json"));
    } catch (const Error &e) {
        qCWarning(lcUi).noquote() << "embedded scenario unreadable:" << e.message();
        return Scenario{};
    }
}

Scenario UiSettings::scenario() const
{
    const QByteArray json = m_settings->value(kScenario).toByteArray();
    if (json.isEmpty())
        return defaultScenario();
    try {
        return scenarioFromJson(json, QStringLiteral("settings"));
    } catch (const Error &e) {
        qCWarning(lcUi).noquote() << "stored scenario ignored:" << e.message();
        return defaultScenario();
    }
}

void UiSettings::setScenario(const Scenario &scenario)
{
    m_settings->setValue(kScenario, scenarioToJson(scenario));
}

QByteArray UiSettings::windowGeometry() const
{
    return m_settings->value(kGeometry).toByteArray();
}

QByteArray UiSettings::windowState() const
{
    return m_settings->value(kState).toByteArray();
}

void UiSettings::setWindow(const QByteArray &geometry, const QByteArray &state)
{
    m_settings->setValue(kGeometry, geometry);
    m_settings->setValue(kState, state);
}

QString UiSettings::language() const
{
    return m_settings->value(kLanguage).toString();
}

void UiSettings::setLanguage(const QString &language)
{
    m_settings->setValue(kLanguage, language);
}

bool UiSettings::plotAutoScale() const
{
    return m_settings->value(kAutoScale, false).toBool();
}

void UiSettings::setPlotAutoScale(bool on)
{
    m_settings->setValue(kAutoScale, on);
}

QString UiSettings::lastDirectory() const
{
    return m_settings->value(kLastDir, QDir::homePath()).toString();
}

void UiSettings::setLastDirectory(const QString &dir)
{
    m_settings->setValue(kLastDir, dir);
}

} // namespace learnid
