#include "ui/RobotChooser.h"

#include "model/ChainModel.h"
#include "model/ModelCheck.h"
#include "service/LogIdentification.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <cmath>

namespace learnid {

namespace {

const QString kPaper = QStringLiteral("paper-2link");
const QString kUrdf = QStringLiteral("urdf");

QString limitText(double value, bool prismatic)
{
    if (!std::isfinite(value))
        return QStringLiteral("\u2013");
    return prismatic ? QString::number(value, 'f', 3)
                     : QString::number(value * 180.0 / M_PI, 'f', 1);
}

} // namespace

RobotChooser::RobotChooser(QWidget *parent)
    : QGroupBox(tr("Robot model"), parent)
    , m_model(new QComboBox(this))
    , m_openUrdf(new QPushButton(tr("Open URDF\u2026"), this))
    , m_file(new QLabel(this))
    , m_summary(new QLabel(this))
    , m_joints(new QTableWidget(this))
{
    m_model->setObjectName(QStringLiteral("robot.model"));
    m_model->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_model->setMinimumContentsLength(16);
    m_openUrdf->setObjectName(QStringLiteral("openUrdfButton"));
    m_summary->setObjectName(QStringLiteral("robotSummary"));
    m_joints->setObjectName(QStringLiteral("robotJoints"));
    m_model->addItem(tr("The paper's 2-link arm (closed form)"), kPaper);
    for (const QString &id : builtInUrdfRobots())
        m_model->addItem(tr("%1 (built-in URDF)").arg(id), id);
    m_model->addItem(tr("URDF file\u2026"), kUrdf);
    m_file->setWordWrap(true);
    m_summary->setWordWrap(true);
    m_joints->setColumnCount(5);
    m_joints->setHorizontalHeaderLabels(
        {tr("Joint"), tr("Lower"), tr("Upper"), tr("Effort"), tr("Mass [kg]")});
    m_joints->setToolTip(tr("Position limits in deg (revolute) or m (prismatic), effort in N m "
                            "or N, as the URDF gives them; the mass of the link the joint "
                            "moves"));
    m_joints->verticalHeader()->hide();
    m_joints->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_joints->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_joints->setMaximumHeight(190);
    m_joints->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);

    auto *grid = new QGridLayout(this);
    grid->addWidget(m_model, 0, 0);
    grid->addWidget(m_openUrdf, 0, 1);
    grid->addWidget(m_file, 1, 0, 1, 2);
    grid->addWidget(m_summary, 2, 0, 1, 2);
    grid->addWidget(m_joints, 3, 0, 1, 2);
    grid->setColumnStretch(0, 1);
    connect(m_model, &QComboBox::activated, this, &RobotChooser::onModelActivated);
    connect(m_openUrdf, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Open the robot's URDF"),
                                                          QFileInfo(m_urdf.file).absolutePath(),
                                                          tr("URDF (*.urdf);;All files (*)"));
        if (!path.isEmpty())
            chooseUrdfFile(path);
    });
}

void RobotChooser::onModelActivated(int index)
{
    const QString id = m_model->itemData(index).toString();
    if (id == kUrdf && m_urdf.file.isEmpty()) {
        m_openUrdf->click(); // a URDF robot needs its file first
        return;
    }
    UrdfRobotSettings urdf;
    if (id == kUrdf)
        urdf.file = m_urdf.file;
    emit robotChosen(id, urdf);
}

void RobotChooser::chooseUrdfFile(const QString &path)
{
    UrdfRobotSettings urdf;
    urdf.file = path;
    m_urdf = urdf;
    emit robotChosen(kUrdf, urdf);
}

void RobotChooser::setEditable(bool editable)
{
    m_model->setEnabled(editable);
    m_openUrdf->setEnabled(editable);
}

QString RobotChooser::summaryText() const
{
    return m_summary->text();
}

void RobotChooser::showRobot(const QString &modelId, const UrdfRobotSettings &urdf,
                             const std::shared_ptr<const RobotModel> &model, const QString &error)
{
    m_urdf = urdf;
    m_model->setCurrentIndex(qMax(0, m_model->findData(modelId)));
    m_file->setText(modelId == kUrdf ? QDir::toNativeSeparators(urdf.file) : QString());
    m_file->setHidden(modelId != kUrdf);
    m_joints->setRowCount(0);
    if (!model) {
        m_summary->setText(tr("Cannot use this robot: %1").arg(error));
        m_summary->setStyleSheet(QStringLiteral("color: #b3261e;"));
        return;
    }
    m_summary->setStyleSheet(QString());
    showModel(*model);
}

void RobotChooser::showModel(const RobotModel &model)
{
    const auto *chain = dynamic_cast<const ChainModel *>(&model);
    if (!chain) {
        m_summary->setText(tr("2 revolute joints in the horizontal plane, no gravity or friction; "
                              "%1 parameters (the paper's a, b, c)")
                               .arg(model.parameterCount()));
        m_joints->hide();
        return;
    }
    const SerialChain &c = chain->chain();
    int revolute = 0;
    double mass = 0.0;
    m_joints->setRowCount(c.dof());
    for (int j = 0; j < c.dof(); ++j) {
        const ChainJoint &joint = c.joints[size_t(j)];
        const bool prismatic = joint.type == JointType::Prismatic;
        revolute += prismatic ? 0 : 1;
        mass += joint.inertial[0];
        const QStringList cells = {
            prismatic ? tr("%1 (prismatic)").arg(joint.name) : joint.name,
            limitText(joint.lower, prismatic), limitText(joint.upper, prismatic),
            std::isfinite(joint.effortLimit) ? QString::number(joint.effortLimit, 'g', 4)
                                             : QStringLiteral("\u2013"),
            QString::number(joint.inertial[0], 'f', 3)};
        for (int col = 0; col < cells.size(); ++col)
            m_joints->setItem(j, col, new QTableWidgetItem(cells[col]));
    }
    m_joints->show();
    const JointTerms &t = chain->jointTerms();
    QStringList terms;
    if (t.armature)
        terms << tr("rotor inertia");
    if (t.viscous)
        terms << tr("viscous");
    if (t.coulomb)
        terms << tr("Coulomb");
    if (t.offset)
        terms << tr("offset");
    const QString joints =
        revolute == c.dof()
            ? tr("%n revolute joint(s)", nullptr, c.dof())
            : tr("%n joint(s) (%1 prismatic)", nullptr, c.dof()).arg(c.dof() - revolute);
    QString text = tr("%1, %2 kg moving; joint terms: %3; %4 base parameters (of %5 standard)")
                       .arg(joints)
                       .arg(mass, 0, 'f', 2)
                       .arg(terms.isEmpty() ? tr("none") : terms.join(QStringLiteral(", ")))
                       .arg(model.parameterCount())
                       .arg(chain->standardCount());
    // The URDF's own values as a real robot's (docs/robots.md §7): a warning, not a refusal.
    const QStringList warnings = modelWarnings(*chain);
    for (const QString &w : warnings)
        text += QLatin1Char('\n') + tr("Warning: %1").arg(w);
    m_summary->setText(text);
    m_summary->setStyleSheet(warnings.isEmpty() ? QString() : QStringLiteral("color: #8a5300;"));
}

} // namespace learnid
