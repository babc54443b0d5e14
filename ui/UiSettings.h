#pragma once

#include "types/Scenario.h"

#include <QByteArray>
#include <QString>
#include <optional>

class QSettings;

namespace learnid {

/// What the window remembers between runs, in a QSettings the caller owns (the application's
/// default in production, a temporary INI file in tests).
class UiSettings
{
public:
    explicit UiSettings(QSettings *settings);

    /// The last scenario of the form, or the embedded paper scenario when none was stored or
    /// the stored one no longer reads.
    Scenario scenario() const;
    /// The embedded default (:/scenarios/paper.json), the paper scenario of docs/design.md §2.
    static Scenario defaultScenario();
    void setScenario(const Scenario &scenario);

    QByteArray windowGeometry() const;
    QByteArray windowState() const;
    void setWindow(const QByteArray &geometry, const QByteArray &state);

    /// "" follows the system locale; else a locale name such as "de" or "zh_CN".
    QString language() const;
    void setLanguage(const QString &language);

    bool plotAutoScale() const;
    void setPlotAutoScale(bool on);

    QString lastDirectory() const;
    void setLastDirectory(const QString &dir);

private:
    QSettings *m_settings;
};

} // namespace learnid
