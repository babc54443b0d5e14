#include "ui/ScenarioForm.h"

#include "identify/LearningLaw.h"
#include "io/ScenarioFile.h"
#include "model/Error.h"

#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>
#include <cmath>

namespace learnid {

namespace {

QLabel *reasonLabel(QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setStyleSheet(QStringLiteral("color: #b3261e;"));
    label->setWordWrap(true);
    label->hide();
    return label;
}

} // namespace

ScenarioForm::ScenarioForm(QWidget *parent)
    : QWidget(parent)
    , m_law(new QComboBox(this))
    , m_otherError(reasonLabel(this))
{
    auto *layout = new QVBoxLayout(this);
    for (const ScenarioFieldGroup &group : scenarioFieldGroups()) {
        auto *box = new QGroupBox(group.title, this);
        auto *grid = new QGridLayout(box);
        grid->setColumnStretch(1, 1);
        int r = 0;
        for (const ScenarioField &field : group.fields) {
            Row row;
            row.field = field;
            row.label = new QLabel(field.label, box);
            row.edit = new QLineEdit(box);
            row.edit->setObjectName(field.key);
            row.edit->setMinimumWidth(90);
            row.edit->setToolTip(tr("Scenario key %1").arg(field.key));
            if (field.kind == ScenarioField::Kind::Vector)
                row.edit->setPlaceholderText(tr("values separated by commas"));
            row.label->setBuddy(row.edit);
            row.reason = reasonLabel(box);
            row.reason->setObjectName(field.key + QStringLiteral(".reason"));
            grid->addWidget(row.label, r, 0);
            grid->addWidget(row.edit, r, 1);
            grid->addWidget(new QLabel(field.unit, box), r, 2);
            grid->addWidget(row.reason, r + 1, 1, 1, 2);
            r += 2;
            connect(row.edit, &QLineEdit::textEdited, this, &ScenarioForm::revalidate);
            m_rows.append(row);
        }
        if (group.fields.constLast().key == QLatin1String("robot.initialParameters")) {
            m_law->setObjectName(QStringLiteral("estimator.law"));
            for (const QString &law : knownLearningLaws())
                m_law->addItem(law == QLatin1String("paper") ? tr("paper-consistent")
                                                             : tr("improved (zero-phase, WLS)"),
                               law);
            grid->addWidget(new QLabel(tr("Estimator law"), box), r, 0);
            grid->addWidget(m_law, r, 1, 1, 2);
            connect(m_law, &QComboBox::activated, this, &ScenarioForm::revalidate);
        }
        layout->addWidget(box);
    }
    layout->addWidget(m_otherError);
    layout->addStretch(1);
    setScenario(Scenario{});
}

void ScenarioForm::setScenario(const Scenario &scenario)
{
    m_base = scenario;
    for (Row &row : m_rows)
        row.edit->setText(formatNumberList(row.field.read(scenario)));
    const int law = m_law->findData(scenario.law);
    m_law->setCurrentIndex(law >= 0 ? law : 0);
    revalidate();
}

QString ScenarioForm::reasonFor(const QString &key) const
{
    for (const Row &row : m_rows)
        if (row.field.key == key)
            return row.reason->isHidden() ? QString() : row.reason->text();
    return {};
}

void ScenarioForm::setParameterNames(const QStringList &names)
{
    for (Row &row : m_rows)
        if (row.field.key == QLatin1String("robot.initialParameters"))
            row.label->setText(tr("Initial parameters (%1)").arg(names.join(QStringLiteral(", "))));
}

void ScenarioForm::setEditable(bool editable)
{
    for (Row &row : m_rows)
        row.edit->setReadOnly(!editable);
    m_law->setEnabled(editable);
}

void ScenarioForm::showReason(Row &row, const QString &reason)
{
    row.reason->setText(reason);
    row.reason->setHidden(reason.isEmpty());
    row.edit->setStyleSheet(reason.isEmpty() ? QString()
                                             : QStringLiteral("border: 1px solid #b3261e;"));
    if (!reason.isEmpty() && m_firstError.isEmpty())
        m_firstError = row.field.key + QStringLiteral(": ") + reason;
}

void ScenarioForm::revalidate()
{
    m_firstError.clear();
    m_otherError->hide();
    Scenario s = m_base;
    s.law = m_law->currentData().toString();
    bool parsed = true;
    for (Row &row : m_rows) {
        QString error;
        const auto values = parseNumberList(row.edit->text(), &error);
        const int expected = row.field.expectedCount;
        if (values && expected > 0 && values->size() != expected) {
            error = expected == 1
                        ? tr("enter one number")
                        : tr("enter %1 numbers, got %2").arg(expected).arg(values->size());
        } else if (values && row.field.kind == ScenarioField::Kind::Integer &&
                   (*values)[0] != std::floor((*values)[0])) {
            error = tr("enter a whole number");
        } else if (values && row.field.kind == ScenarioField::Kind::Integer &&
                   ((*values)[0] < row.field.minimum || (*values)[0] > row.field.maximum)) {
            error = tr("enter a whole number from %1 to %2")
                        .arg(row.field.minimum, 0, 'f', 0)
                        .arg(row.field.maximum, 0, 'f', 0);
        }
        showReason(row, error);
        if (!error.isEmpty())
            parsed = false;
        else
            row.field.write(s, *values);
    }
    if (parsed) {
        try {
            validateScenario(s);
        } catch (const Error &e) {
            // validateScenario() says "<key path>: <problem>"; show the problem at its field.
            const QString message = e.message();
            const int colon = message.indexOf(QStringLiteral(": "));
            const QString key = colon > 0 ? message.left(colon) : QString();
            const QString problem = colon > 0 ? message.mid(colon + 2) : message;
            bool shown = false;
            for (Row &row : m_rows) {
                if (keyBelongsTo(key, row.field.key)) {
                    showReason(row, key == row.field.key ? problem
                                                         : key + QStringLiteral(": ") + problem);
                    shown = true;
                    break;
                }
            }
            if (!shown) {
                m_otherError->setText(message);
                m_otherError->show();
                m_firstError = message;
            }
            parsed = false;
        }
    }
    m_valid = parsed;
    if (parsed)
        m_current = s;
    emit edited(m_valid);
}

} // namespace learnid
