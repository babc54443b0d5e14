#include "ui/PayloadForm.h"

#include "io/ScenarioFile.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "ui/ScenarioFields.h"

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
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

Eigen::VectorXd one(double v)
{
    return Eigen::VectorXd::Constant(1, v);
}

} // namespace

PayloadForm::PayloadForm(QWidget *parent)
    : QWidget(parent)
    , m_link(new QComboBox(this))
    , m_linkReason(reasonLabel(this))
    , m_otherError(reasonLabel(this))
{
    m_link->setObjectName(QStringLiteral("payload.link"));
    m_link->setToolTip(tr("Scenario key %1").arg(QStringLiteral("payload.link")));
    m_linkReason->setObjectName(QStringLiteral("payload.link.reason"));
    m_otherError->setObjectName(QStringLiteral("payloadOtherError"));
    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setColumnStretch(1, 1);
    auto *linkLabel = new QLabel(tr("Mounted on link"), this);
    linkLabel->setBuddy(m_link);
    grid->addWidget(linkLabel, 0, 0);
    grid->addWidget(m_link, 0, 1, 1, 2);
    grid->addWidget(m_linkReason, 1, 1, 1, 2);
    connect(m_link, &QComboBox::activated, this, &PayloadForm::revalidate);

    const auto makeRow = [](const char *key, int count = 1, bool emptyAllowed = false,
                            bool integer = false) {
        Row r;
        r.key = QLatin1String(key);
        r.count = count;
        r.emptyAllowed = emptyAllowed;
        r.integer = integer;
        return r;
    };
    Row mass = makeRow("payload.prior.mass");
    mass.read = [](const Scenario &s) {
        return s.payload.mass > 0.0 ? one(s.payload.mass) : Eigen::VectorXd();
    };
    mass.write = [](Scenario &s, const Eigen::VectorXd &v) {
        s.payload.mass = v[0];
    };
    addRow(mass, tr("Mass (prior)"), QStringLiteral("kg"), tr("the technician's estimate"));
    Row com = makeRow("payload.prior.com", 3);
    com.read = [](const Scenario &s) {
        return Eigen::VectorXd(s.payload.com);
    };
    com.write = [](Scenario &s, const Eigen::VectorXd &v) {
        s.payload.com = v;
    };
    addRow(com, tr("Centre of mass (prior) x, y, z"), QStringLiteral("m"), {});
    Row inertia = makeRow("payload.prior.inertia", 6, true);
    inertia.read = [](const Scenario &s) {
        return s.payload.inertia;
    };
    inertia.write = [](Scenario &s, const Eigen::VectorXd &v) {
        s.payload.inertia = v;
    };
    addRow(inertia, tr("Inertia about it (prior) Ixx, Ixy, Iyy, Ixz, Iyz, Izz"),
           QStringLiteral("kg m\u00b2"), tr("empty: a solid sphere"));
    Row radius = makeRow("payload.bound.radius");
    radius.read = [](const Scenario &s) {
        return one(s.payload.radius);
    };
    radius.write = [](Scenario &s, const Eigen::VectorXd &v) {
        s.payload.radius = v[0];
    };
    addRow(radius, tr("Bound: sphere around the flange, radius"), QStringLiteral("m"), {});
    Row box = makeRow("payload.bound.box", 6, true);
    box.read = [](const Scenario &s) {
        return s.payload.box;
    };
    box.write = [](Scenario &s, const Eigen::VectorXd &v) {
        s.payload.box = v;
    };
    addRow(box, tr("or a box x0, y0, z0, x1, y1, z1"), QStringLiteral("m"),
           tr("empty: the sphere"));
    Row baseline = makeRow("payload.baselineTrials", 1, false, true);
    baseline.read = [](const Scenario &s) {
        return one(s.payload.baselineTrials);
    };
    baseline.write = [](Scenario &s, const Eigen::VectorXd &v) {
        s.payload.baselineTrials = int(v[0]);
    };
    addRow(baseline, tr("Baseline trials without the payload"), {}, {});
    Row trials = makeRow("estimator.iterations", 1, false, true);
    trials.read = [](const Scenario &s) {
        return one(s.iterations);
    };
    trials.write = [](Scenario &s, const Eigen::VectorXd &v) {
        s.iterations = int(v[0]);
    };
    addRow(trials, tr("Payload trials"), {}, {});
    grid->addWidget(m_otherError, grid->rowCount(), 0, 1, 3);
    setScenario(Scenario{});
}

void PayloadForm::addRow(Row row, const QString &label, const QString &unit,
                         const QString &placeholder)
{
    auto *grid = static_cast<QGridLayout *>(layout());
    const int r = grid->rowCount();
    row.edit = new QLineEdit(this);
    row.edit->setObjectName(row.key);
    row.edit->setToolTip(tr("Scenario key %1").arg(row.key));
    row.edit->setPlaceholderText(placeholder);
    row.reason = reasonLabel(this);
    row.reason->setObjectName(row.key + QStringLiteral(".reason"));
    auto *name = new QLabel(label, this);
    name->setWordWrap(true);
    name->setBuddy(row.edit);
    grid->addWidget(name, r, 0);
    grid->addWidget(row.edit, r, 1);
    grid->addWidget(new QLabel(unit, this), r, 2);
    grid->addWidget(row.reason, r + 1, 1, 1, 2);
    connect(row.edit, &QLineEdit::textEdited, this, &PayloadForm::revalidate);
    m_rows.append(row);
}

void PayloadForm::setScenario(const Scenario &scenario)
{
    m_base = scenario;
    if (!m_base.payload.enabled) {
        m_base.payload = PayloadSettings();
        m_base.payload.enabled = true;
    }
    m_link->clear();
    try {
        const auto chain =
            std::dynamic_pointer_cast<const ChainModel>(makeRobotModel(m_base.model, m_base.urdf));
        if (chain && !chain->chain().joints.empty()) {
            m_link->addItem(tr("the tip (%1)").arg(chain->chain().joints.back().link), QString());
            for (const ChainJoint &j : chain->chain().joints) {
                m_link->addItem(j.link, j.link);
                for (const FixedLink &fixed : j.fixedLinks) { // a flange or tool frame
                    m_link->addItem(tr("%1 (on %2)").arg(fixed.name, j.link), fixed.name);
                    m_link->setItemData(
                        m_link->count() - 1,
                        tr("%1 is fixed to %2 and moves with it").arg(fixed.name, j.link),
                        Qt::ToolTipRole);
                }
            }
        }
    } catch (const Error &) {
        // validateScenario() names the model's problem below.
    }
    const int link = m_link->findData(m_base.payload.link);
    if (link >= 0) {
        m_link->setCurrentIndex(link);
    } else if (!m_base.payload.link.isEmpty()) { // shown as it is, and refused
        m_link->addItem(m_base.payload.link, m_base.payload.link);
        m_link->setCurrentIndex(m_link->count() - 1);
    }
    for (Row &row : m_rows)
        row.edit->setText(formatNumberList(row.read(m_base)));
    revalidate();
}

QString PayloadForm::reasonFor(const QString &key) const
{
    if (key == QLatin1String("payload.link"))
        return m_linkReason->isHidden() ? QString() : m_linkReason->text();
    for (const Row &row : m_rows)
        if (row.key == key)
            return row.reason->isHidden() ? QString() : row.reason->text();
    return {};
}

QLineEdit *PayloadForm::field(const QString &key) const
{
    for (const Row &row : m_rows)
        if (row.key == key)
            return row.edit;
    return nullptr;
}

void PayloadForm::setEditable(bool editable)
{
    m_link->setEnabled(editable);
    for (Row &row : m_rows)
        row.edit->setReadOnly(!editable);
}

void PayloadForm::showReason(QLabel *reason, QWidget *edit, const QString &key, const QString &text)
{
    reason->setText(text);
    reason->setHidden(text.isEmpty());
    edit->setStyleSheet(text.isEmpty() ? QString() : QStringLiteral("border: 1px solid #b3261e;"));
    if (!text.isEmpty() && m_firstError.isEmpty())
        m_firstError = key + QStringLiteral(": ") + text;
}

void PayloadForm::revalidate()
{
    m_firstError.clear();
    m_otherError->hide();
    showReason(m_linkReason, m_link, QStringLiteral("payload.link"), QString());
    Scenario s = m_base;
    s.payload.link = m_link->currentData().toString();
    bool parsed = true;
    for (Row &row : m_rows) {
        QString error;
        std::optional<Eigen::VectorXd> values;
        if (row.emptyAllowed && row.edit->text().trimmed().isEmpty())
            values = Eigen::VectorXd();
        else
            values = parseNumberList(row.edit->text(), &error);
        if (values && values->size() > 0 && values->size() != row.count) {
            error = row.count == 1
                        ? tr("enter one number")
                        : tr("enter %1 numbers, got %2").arg(row.count).arg(values->size());
        } else if (values && !row.emptyAllowed && values->size() == 0) {
            error = row.count == 1 ? tr("enter one number") : tr("enter %1 numbers").arg(row.count);
        } else if (values && row.integer && (*values)[0] != std::floor((*values)[0])) {
            error = tr("enter a whole number");
        }
        showReason(row.reason, row.edit, row.key, error);
        if (error.isEmpty())
            row.write(s, *values);
        else
            parsed = false;
    }
    if (parsed) {
        try {
            validateScenario(s); // its payload keys on the robot's model, each named
        } catch (const Error &e) {
            // "<key path>: <problem>"; shown at its field, else below the form.
            const QString message = e.message();
            const int colon = message.indexOf(QStringLiteral(": "));
            const QString key = colon > 0 ? message.left(colon) : QString();
            const QString problem = colon > 0 ? message.mid(colon + 2) : message;
            m_firstError = message;
            bool shown = false;
            if (keyBelongsTo(key, QStringLiteral("payload.link"))) {
                showReason(m_linkReason, m_link, key, problem);
                shown = true;
            }
            for (Row &row : m_rows) {
                if (!shown && keyBelongsTo(key, row.key)) {
                    showReason(row.reason, row.edit, row.key, key == row.key ? problem : message);
                    shown = true;
                }
            }
            if (!shown) {
                m_otherError->setText(message);
                m_otherError->show();
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
