#include "ui/ScenarioForm.h"

#include "identify/LearningLaw.h"
#include "io/PathCsv.h"
#include "io/ScenarioFile.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "session/RobotScenario.h"
#include "ui/RobotChooser.h"
#include "ui/WaypointEditor.h"

#include <QComboBox>
#include <QFileInfo>
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
    , m_sensor(new QComboBox(this))
    , m_robot(new RobotChooser(this))
    , m_waypoints(new WaypointEditor(this))
    , m_otherError(reasonLabel(this))
{
    connect(m_waypoints, &WaypointEditor::pathFileChosen, this, &ScenarioForm::usePathFile);
    connect(m_waypoints, &WaypointEditor::waypointsChosen, this, &ScenarioForm::useWaypoints);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_robot);
    connect(m_robot, &RobotChooser::robotChosen, this, &ScenarioForm::chooseRobot);
    connect(m_waypoints, &WaypointEditor::edited, this, &ScenarioForm::revalidate);
    for (const ScenarioFieldGroup &group : scenarioFieldGroups()) {
        auto *box = new QGroupBox(group.title, this);
        auto *grid = new QGridLayout(box);
        grid->setColumnStretch(1, 1);
        int r = 0;
        for (const ScenarioField &field : group.fields) {
            Row row;
            row.field = field;
            row.label = new QLabel(field.label, box);
            row.label->setWordWrap(true); // "Initial parameters (57 base parameters)"
            row.edit = new QLineEdit(box);
            row.edit->setObjectName(field.key);
            row.edit->setMinimumWidth(90);
            row.edit->setToolTip(tr("Scenario key %1").arg(field.key));
            if (field.emptyTakesRobot)
                row.edit->setPlaceholderText(tr("URDF robots: empty takes the robot's"));
            else if (field.kind == ScenarioField::Kind::Vector)
                row.edit->setPlaceholderText(tr("values separated by commas"));
            row.label->setBuddy(row.edit);
            row.reason = reasonLabel(box);
            row.reason->setObjectName(field.key + QStringLiteral(".reason"));
            grid->addWidget(row.label, r, 0);
            grid->addWidget(row.edit, r, 1);
            row.unit = new QLabel(field.unit, box);
            grid->addWidget(row.unit, r, 2);
            grid->addWidget(row.reason, r + 1, 1, 1, 2);
            r += 2;
            connect(row.edit, &QLineEdit::textEdited, this, &ScenarioForm::revalidate);
            m_rows.append(row);
        }
        if (group.fields.constFirst().key == QLatin1String("path.start"))
            grid->addWidget(m_waypoints, r++, 0, 1, 3);
        if (group.fields.constLast().key == QLatin1String("robot.initialParameters")) {
            m_law->setObjectName(QStringLiteral("estimator.law"));
            for (const QString &law : knownLearningLaws())
                m_law->addItem(law == QLatin1String("paper") ? tr("paper-consistent")
                                                             : tr("improved (zero-phase, WLS)"),
                               law);
            grid->addWidget(new QLabel(tr("Estimator law"), box), r, 0);
            grid->addWidget(m_law, r++, 1, 1, 2);
            connect(m_law, &QComboBox::activated, this, &ScenarioForm::revalidate);
            // Joint torque sensors do not see the rotors (docs/method.md §2.6).
            m_sensor->setObjectName(QStringLiteral("estimator.jointTorqueSensor"));
            m_sensor->setToolTip(tr("Scenario key %1").arg(m_sensor->objectName()));
            m_sensor->addItem(tr("the drives (motor current)"), false);
            m_sensor->addItem(tr("joint torque sensors behind the gears"), true);
            grid->addWidget(new QLabel(tr("Torque measured by"), box), r, 0);
            grid->addWidget(m_sensor, r, 1, 1, 2);
            connect(m_sensor, &QComboBox::activated, this, &ScenarioForm::revalidate);
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
    m_model.reset();
    m_modelError.clear();
    try {
        m_model = makeRobotModel(scenario.model, scenario.urdf);
        if (!m_model)
            m_modelError = tr("unknown model \"%1\"").arg(scenario.model);
    } catch (const Error &e) {
        m_modelError = e.message();
    }
    m_robot->showRobot(scenario.model, scenario.urdf, m_model, m_modelError);
    const QStringList joints = m_model ? jointNames(*m_model) : QStringList();
    QList<bool> prismatic;
    if (const auto *chain = dynamic_cast<const ChainModel *>(m_model.get()))
        for (const ChainJoint &joint : chain->chain().joints)
            prismatic << (joint.type == JointType::Prismatic);
    m_waypoints->setPath(scenario.path, joints, prismatic, isUrdfModel(scenario.model));
    updatePathRows();
    for (Row &row : m_rows)
        row.edit->setText(formatNumberList(row.field.read(scenario)));
    const int law = m_law->findData(scenario.law);
    m_law->setCurrentIndex(law >= 0 ? law : 0);
    m_sensor->setCurrentIndex(scenario.estimator.jointTorqueSensor ? 1 : 0);
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
    const QString label =
        names.size() > 4
            ? tr("Initial parameters (%n base parameter(s))", nullptr, int(names.size()))
            : tr("Initial parameters (%1)").arg(names.join(QStringLiteral(", ")));
    for (Row &row : m_rows)
        if (row.field.key == QLatin1String("robot.initialParameters"))
            row.label->setText(label);
}

void ScenarioForm::chooseRobot(const QString &modelId, const UrdfRobotSettings &urdf)
{
    try {
        setScenario(scenarioForRobot(modelId, urdf));
    } catch (const Error &e) {
        m_model.reset();
        m_robot->showRobot(modelId, urdf, nullptr, e.message());
        m_otherError->setText(tr("robot.model: %1").arg(e.message()));
        m_otherError->show();
        m_firstError = m_otherError->text();
        m_valid = false;
        emit edited(false);
    }
}

// The line's fields for the paper's line only.
void ScenarioForm::updatePathRows()
{
    const PathKind kind = m_base.path.kind;
    for (Row &row : m_rows) {
        const bool shown = !row.field.lineOnly || kind == PathKind::Line;
        row.label->setVisible(shown);
        row.edit->setVisible(shown);
        row.unit->setVisible(shown);
        if (!shown)
            row.reason->hide();
    }
    m_waypoints->setVisible(kind != PathKind::Line || isUrdfModel(m_base.model));
}

void ScenarioForm::usePathFile(const QString &path)
{
    try {
        const PathSamples samples = readPathCsvFile(path, m_model ? m_model->dof() : 0);
        Scenario s = scenario().value_or(m_base); // the edits so far, when they are valid
        s.path.kind = PathKind::File;
        s.path.file = QFileInfo(path).absoluteFilePath();
        s.path.fileTimes = samples.t;
        s.path.fileAngles = samples.q;
        setScenario(s);
    } catch (const Error &e) {
        m_otherError->setText(tr("path.file: %1").arg(e.message()));
        m_otherError->show();
    }
}

void ScenarioForm::useWaypoints()
{
    Scenario s = scenario().value_or(m_base);
    s.path.kind = PathKind::Waypoints;
    if (s.path.waypoints.size() < 2 && m_model) // none kept: the robot's default path
        s.path.waypoints = scenarioForRobot(s.model, s.urdf).path.waypoints;
    setScenario(s);
}

void ScenarioForm::setEditable(bool editable)
{
    for (Row &row : m_rows)
        row.edit->setReadOnly(!editable);
    m_law->setEnabled(editable);
    m_sensor->setEnabled(editable);
    m_robot->setEditable(editable);
    m_waypoints->setEditable(editable);
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
    s.estimator.jointTorqueSensor = m_sensor->currentData().toBool();
    bool parsed = true;
    for (Row &row : m_rows) {
        if (row.field.emptyTakesRobot && row.edit->text().trimmed().isEmpty() &&
            isUrdfModel(s.model)) {
            showReason(row, QString());
            row.field.write(s, Eigen::VectorXd());
            continue;
        }
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
    QString pathError;
    if (!m_waypoints->readInto(s.path, &pathError)) {
        if (m_firstError.isEmpty())
            m_firstError = pathError;
        parsed = false;
    }
    if (parsed && !m_model) {
        m_otherError->setText(tr("robot.model: %1").arg(m_modelError));
        m_otherError->show();
        m_firstError = m_otherError->text();
        parsed = false;
    }
    if (parsed) {
        try {
            validateScenario(s);
            const QString limits = waypointLimitError(*m_model, s.path.waypoints);
            if (s.path.kind == PathKind::Waypoints && !limits.isEmpty()) {
                m_waypoints->showLimitError(limits);
                m_firstError = limits;
                parsed = false;
            }
        } catch (const Error &e) {
            // validateScenario() says "<key path>: <problem>"; show the problem at its field.
            const QString message = e.message();
            const int colon = message.indexOf(QStringLiteral(": "));
            const QString key = colon > 0 ? message.left(colon) : QString();
            const QString problem = colon > 0 ? message.mid(colon + 2) : message;
            bool shown = keyBelongsTo(key, QStringLiteral("path.waypoints"));
            if (shown) {
                m_waypoints->showReason(message);
                m_firstError = message;
            }
            for (Row &row : m_rows) {
                if (shown)
                    break;
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
