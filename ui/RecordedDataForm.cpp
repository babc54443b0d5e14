#include "ui/RecordedDataForm.h"
#include "ui/WidgetFactory.h"

#include "model/Error.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace learnid {

namespace {

// The double pendulum's logs (docs/cli.md): what a log whose columns are not named t, q1, ...
// needs.
const char *const kColumnsExample = "t=time,q=pos_meas%1,dq=vel_meas%1,tau=tau_meas%1";

// A log by its file name; the whole path in the tooltip and Qt::UserRole.
void addLog(QListWidget *list, const QString &path)
{
    auto *item = new QListWidgetItem(QFileInfo(path).fileName(), list);
    item->setData(Qt::UserRole, path);
    item->setToolTip(QDir::toNativeSeparators(path));
}

} // namespace

QStringList chooseRecordedDataPaths(QWidget *parent, RecordedDataPath purpose,
                                    const QString &suggested)
{
    const auto one = [](const QString &path) {
        return path.isEmpty() ? QStringList() : QStringList{path};
    };
    const QString logs = RecordedDataForm::tr("Robot logs (*.csv);;All files (*)");
    switch (purpose) {
    case RecordedDataPath::RobotUrdf:
        return one(
            QFileDialog::getOpenFileName(parent, RecordedDataForm::tr("Robot URDF"), suggested,
                                         RecordedDataForm::tr("URDF (*.urdf);;All files (*)")));
    case RecordedDataPath::TrainingLogs:
        return QFileDialog::getOpenFileNames(parent, RecordedDataForm::tr("Logs to identify from"),
                                             suggested, logs);
    case RecordedDataPath::ValidationLogs:
        return QFileDialog::getOpenFileNames(parent, RecordedDataForm::tr("Logs to validate on"),
                                             suggested, logs);
    case RecordedDataPath::GainsScenario:
        return one(QFileDialog::getOpenFileName(
            parent, RecordedDataForm::tr("Scenario with the controller gains"), suggested,
            RecordedDataForm::tr("Scenario files (*.json);;All files (*)")));
    case RecordedDataPath::ParameterFile:
        return one(QFileDialog::getSaveFileName(
            parent, RecordedDataForm::tr("Export parameter file"), suggested,
            RecordedDataForm::tr("Parameter files (*.json)")));
    case RecordedDataPath::IdentifiedUrdf:
        return one(QFileDialog::getSaveFileName(parent, RecordedDataForm::tr("Export URDF"),
                                                suggested, RecordedDataForm::tr("URDF (*.urdf)")));
    }
    return {};
}

RecordedDataForm::RecordedDataForm(QWidget *parent)
    : QWidget(parent)
    , m_robot(new QComboBox(this))
    , m_urdf(new QLineEdit(this))
    , m_browseUrdf(namedButton(tr("Browse\u2026"), "browseUrdfButton", this))
    , m_training(new QListWidget(this))
    , m_validation(new QListWidget(this))
    , m_columns(new QLineEdit(this))
    , m_gains(new QLineEdit(this))
    , m_browseGains(namedButton(tr("Browse\u2026"), "browseGainsButton", this))
{
    m_robot->setObjectName(QStringLiteral("recordedRobot"));
    m_urdf->setObjectName(QStringLiteral("recordedUrdf"));
    m_training->setObjectName(QStringLiteral("trainingLogs"));
    m_validation->setObjectName(QStringLiteral("validationLogs"));
    m_columns->setObjectName(QStringLiteral("logColumns"));
    m_gains->setObjectName(QStringLiteral("gainsScenario"));
    for (const QString &id : builtInUrdfRobots())
        m_robot->addItem(tr("%1 (built-in URDF)").arg(id), id);
    m_robot->addItem(tr("URDF file\u2026"), QString());
    m_robot->setCurrentIndex(qMax(0, m_robot->findData(QStringLiteral("double-pendulum"))));
    m_urdf->setPlaceholderText(tr("the robot's URDF file"));
    m_columns->setPlaceholderText(QLatin1String(kColumnsExample));
    m_columns->setToolTip(
        tr("The logs' column names as learnid-cli identify --columns takes them: t=, q=, dq=, "
           "tau= with %1 for the joint number. Empty: t, q%1, dq%1, tau%1."));
    m_gains->setPlaceholderText(tr("none: the parameter file holds the model alone"));
    m_gains->setToolTip(tr("A scenario of this robot whose controller gains the parameter file "
                           "records; the logs do not say which gains they were recorded with."));
    const QStringList termNames = {tr("armature"), tr("viscous"), tr("Coulomb"), tr("offset")};
    auto *terms = new QHBoxLayout;
    terms->setContentsMargins(0, 0, 0, 0);
    for (const QString &name : termNames) {
        auto *box = new QCheckBox(name, this);
        box->setChecked(name != termNames.front()); // as learnid-cli: viscous, Coulomb, offset
        m_terms << box;
        terms->addWidget(box);
    }
    terms->addStretch(1);

    auto *urdfRow = new QHBoxLayout;
    urdfRow->addWidget(m_urdf, 1);
    urdfRow->addWidget(m_browseUrdf);
    auto *gainsRow = new QHBoxLayout;
    gainsRow->addWidget(m_gains, 1);
    gainsRow->addWidget(m_browseGains);
    auto *layout = new QFormLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addRow(tr("Robot:"), m_robot);
    layout->addRow(QString(), urdfRow);
    layout->addRow(tr("Training logs:"),
                   logList(m_training, RecordedDataPath::TrainingLogs, "addTrainingLogsButton",
                           "removeTrainingLogsButton"));
    layout->addRow(tr("Validation logs:"),
                   logList(m_validation, RecordedDataPath::ValidationLogs,
                           "addValidationLogsButton", "removeValidationLogsButton"));
    layout->addRow(tr("Columns:"), m_columns);
    layout->addRow(tr("Joint terms:"), terms);
    layout->addRow(tr("Gains from:"), gainsRow);

    connect(m_robot, &QComboBox::currentIndexChanged, this, &RecordedDataForm::updateUrdfField);
    connect(m_browseUrdf, &QPushButton::clicked, this, [this] {
        const QStringList paths = choose(RecordedDataPath::RobotUrdf);
        if (!paths.isEmpty())
            m_urdf->setText(QDir::toNativeSeparators(paths.constFirst()));
    });
    connect(m_browseGains, &QPushButton::clicked, this, [this] {
        const QStringList paths = choose(RecordedDataPath::GainsScenario);
        if (!paths.isEmpty())
            m_gains->setText(QDir::toNativeSeparators(paths.constFirst()));
    });
    updateUrdfField();
}

QWidget *RecordedDataForm::logList(QListWidget *list, RecordedDataPath purpose, const char *addName,
                                   const char *removeName)
{
    auto *box = new QWidget(this);
    list->setSelectionMode(QAbstractItemView::ExtendedSelection);
    list->setMinimumHeight(48);
    list->setMaximumHeight(66);
    auto *add = namedButton(tr("Add\u2026"), addName, box);
    auto *remove = namedButton(tr("Remove"), removeName, box);
    auto *buttons = new QVBoxLayout;
    buttons->addWidget(add);
    buttons->addWidget(remove);
    buttons->addStretch(1);
    auto *layout = new QHBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(list, 1);
    layout->addLayout(buttons);
    connect(add, &QPushButton::clicked, this, [this, list, purpose] {
        for (const QString &path : choose(purpose))
            addLog(list, path);
    });
    connect(remove, &QPushButton::clicked, this, [list] { qDeleteAll(list->selectedItems()); });
    return box;
}

QStringList RecordedDataForm::choose(RecordedDataPath purpose)
{
    const QStringList paths = m_chooser ? m_chooser(purpose, m_startDir)
                                        : chooseRecordedDataPaths(this, purpose, m_startDir);
    if (!paths.isEmpty()) {
        m_startDir = QFileInfo(paths.constFirst()).absolutePath();
        emit directoryUsed(m_startDir);
    }
    return paths;
}

void RecordedDataForm::updateUrdfField()
{
    const bool file = m_robot->currentData().toString().isEmpty();
    m_urdf->setVisible(file);
    m_browseUrdf->setVisible(file);
}

void RecordedDataForm::setRobot(const QString &robot)
{
    const int builtIn = m_robot->findData(robot);
    m_robot->setCurrentIndex(builtIn >= 0 ? builtIn : m_robot->count() - 1);
    if (builtIn < 0)
        m_urdf->setText(QDir::toNativeSeparators(robot));
}

void RecordedDataForm::setTrainingLogs(const QStringList &paths)
{
    m_training->clear();
    for (const QString &path : paths)
        addLog(m_training, path);
}

void RecordedDataForm::setValidationLogs(const QStringList &paths)
{
    m_validation->clear();
    for (const QString &path : paths)
        addLog(m_validation, path);
}

void RecordedDataForm::setColumns(const QString &spec)
{
    m_columns->setText(spec);
}

void RecordedDataForm::setGainsScenario(const QString &path)
{
    m_gains->setText(QDir::toNativeSeparators(path));
}

namespace {
QStringList paths(const QListWidget *list)
{
    QStringList out;
    for (int i = 0; i < list->count(); ++i)
        out << list->item(i)->data(Qt::UserRole).toString();
    return out;
}
} // namespace

QStringList RecordedDataForm::trainingLogs() const
{
    return paths(m_training);
}

QStringList RecordedDataForm::validationLogs() const
{
    return paths(m_validation);
}

QString RecordedDataForm::gainsScenario() const
{
    return QDir::fromNativeSeparators(m_gains->text().trimmed());
}

void RecordedDataForm::setEditable(bool editable)
{
    setEnabled(editable);
}

std::optional<LogIdentificationRequest> RecordedDataForm::request(QString *error) const
{
    error->clear();
    LogIdentificationRequest r;
    r.robot = m_robot->currentData().toString();
    if (r.robot.isEmpty())
        r.robot = QDir::fromNativeSeparators(m_urdf->text().trimmed());
    r.trainingLogs = trainingLogs();
    r.validationLogs = validationLogs();
    r.terms = JointTerms{m_terms[0]->isChecked(), m_terms[1]->isChecked(), m_terms[2]->isChecked(),
                         m_terms[3]->isChecked()};
    if (r.robot.isEmpty())
        *error = tr("choose the robot's URDF file");
    else if (r.trainingLogs.isEmpty())
        *error = tr("add at least one training log (the logs to identify from)");
    if (!error->isEmpty())
        return std::nullopt;
    try {
        if (!m_columns->text().trimmed().isEmpty())
            r.columns = parseLogColumns(m_columns->text().trimmed());
    } catch (const Error &e) {
        *error = e.message();
        return std::nullopt;
    }
    return r;
}

} // namespace learnid
