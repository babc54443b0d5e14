#pragma once

#include "types/Scenario.h"

#include <QWidget>
#include <functional>
#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;

namespace learnid {

/// The payload section of a scenario as a form (docs/scenario.md, payload): the link it is
/// fixed to, the technician's prior (mass, centre of mass, inertia about it), the bound its mass
/// must lie in (a sphere, or a box), the baseline trials without the payload and the payload
/// trials. Every edit is parsed and validated at once (validateScenario()); the reason a value is
/// refused is shown next to its field, named by its scenario key. The rest of the scenario is
/// kept from setScenario().
class PayloadForm : public QWidget
{
    Q_OBJECT

public:
    explicit PayloadForm(QWidget *parent = nullptr);

    /// A scenario without a payload section gets one: the tip, no mass yet, the default bound.
    void setScenario(const Scenario &scenario);
    /// The edited scenario, or nullopt while a field is refused.
    std::optional<Scenario> scenario() const
    {
        return m_valid ? std::optional(m_current) : std::nullopt;
    }
    bool isValid() const { return m_valid; }
    /// The first refused field's key and reason ("payload.prior.mass: must be positive"), or "".
    QString firstError() const { return m_firstError; }
    /// The reason shown next to the field of a scenario key, "" when it is accepted.
    QString reasonFor(const QString &key) const;
    /// The line edit of a key ("payload.prior.mass"), for tests; null for an unknown key.
    QLineEdit *field(const QString &key) const;
    QComboBox *linkChoice() const { return m_link; }
    void setEditable(bool editable);

signals:
    /// After every edit; scenario() holds the result when valid.
    void edited(bool valid);

private:
    struct Row
    {
        QString key;
        int count = 1;             ///< values it takes
        bool emptyAllowed = false; ///< empty: not given (a sphere's inertia, the sphere bound)
        bool integer = false;
        std::function<Eigen::VectorXd(const Scenario &)> read;
        std::function<void(Scenario &, const Eigen::VectorXd &)> write;
        QLineEdit *edit = nullptr;
        QLabel *reason = nullptr;
    };

    void addRow(Row row, const QString &label, const QString &unit, const QString &placeholder);
    void revalidate();
    void showReason(QLabel *reason, QWidget *edit, const QString &key, const QString &text);

    QComboBox *m_link;
    QLabel *m_linkReason;
    QLabel *m_otherError;
    QList<Row> m_rows;
    Scenario m_base;
    Scenario m_current;
    bool m_valid = false;
    QString m_firstError;
};

} // namespace learnid
