#include "ui/PreTrialCheckView.h"

#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace learnid {

namespace {

QTableWidgetItem *cell(const QString &text, Qt::Alignment align = Qt::AlignRight | Qt::AlignVCenter)
{
    auto *item = new QTableWidgetItem(text);
    item->setTextAlignment(align);
    item->setFlags(Qt::ItemIsEnabled);
    return item;
}

} // namespace

PreTrialCheckView::PreTrialCheckView(QWidget *parent)
    : QWidget(parent)
    , m_verdict(new QLabel(this))
    , m_duration(new QLabel(this))
    , m_stability(new QLabel(this))
    , m_torques(new QTableWidget(0, 5, this))
{
    m_verdict->setObjectName(QStringLiteral("checkVerdict"));
    m_verdict->setWordWrap(true);
    m_verdict->setMargin(6);
    m_stability->setWordWrap(true);
    m_duration->setWordWrap(true); // a long line (German) must not widen the window
    // Units on a second header line, and columns as wide as their longest word: in German
    // ("Spitze", "Auslastung", "Schwerkraft") a header cut to fit the panel cannot be read; the
    // table scrolls sideways instead when the panel is narrower.
    QStringList headers{tr("Joint"), tr("Peak [N m]"), tr("Limit [N m]"), tr("Use"), tr("Gravity")};
    for (QString &h : headers)
        h.replace(QStringLiteral(" ["), QStringLiteral("\n["));
    m_torques->setHorizontalHeaderLabels(headers);
    m_torques->horizontalHeaderItem(4)->setToolTip(
        tr("The largest torque holding the arm against gravity takes on this path, as a share "
           "of the limit"));
    m_torques->verticalHeader()->hide();
    m_torques->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_torques->horizontalHeader()->setStretchLastSection(true);
    m_torques->setSelectionMode(QAbstractItemView::NoSelection);
    m_torques->setMaximumHeight(150);

    auto *form = new QFormLayout;
    form->addRow(tr("Planned motion:"), m_duration);
    form->addRow(tr("Closed loop:"), m_stability);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_verdict);
    layout->addLayout(form);
    layout->addWidget(m_torques);
    clear(tr("Connect a robot to plan the first trial."));
}

void PreTrialCheckView::clear(const QString &why)
{
    m_verdict->setText(why);
    m_verdict->setStyleSheet(QStringLiteral("background: #eeeeee;"));
    m_duration->setText(QStringLiteral("\u2013"));
    m_stability->setText(QStringLiteral("\u2013"));
    m_torques->setRowCount(0);
}

QString PreTrialCheckView::verdictText() const
{
    return m_verdict->text();
}

void PreTrialCheckView::setCheck(const PreTrialCheck &check, int nextTrial)
{
    if (check.passed()) {
        m_verdict->setText(tr("Trial %1: check passed, the trial may run.").arg(nextTrial));
        m_verdict->setStyleSheet(QStringLiteral("background: #e6f4e6; color: #1e5e1e;"));
    } else {
        m_verdict->setText(tr("Trial %1 refused: %2").arg(nextTrial).arg(check.reason()));
        m_verdict->setStyleSheet(QStringLiteral("background: #fbe9e7; color: #8c1d18;"));
    }
    if (!check.planningError.isEmpty()) {
        m_duration->setText(tr("no plan"));
        m_stability->setText(QStringLiteral("\u2013"));
        m_torques->setRowCount(0);
        return;
    }
    const SafetyVerdict &v = check.verdict;
    m_duration->setText(tr("%1 s motion, %2 s with rests, %3 samples")
                            .arg(v.motionDuration, 0, 'f', 3)
                            .arg(check.plan.desired.duration(), 0, 'f', 3)
                            .arg(check.plan.samples()));
    if (!v.physical)
        m_stability->setText(tr("estimate not physical (mass matrix not positive definite)"));
    else if (v.stable)
        m_stability->setText(tr("stable: max |z| = %1, decay rate %2 1/s")
                                 .arg(v.worstSpectralRadius, 0, 'f', 6)
                                 .arg(v.worstDecayRate, 0, 'g', 4));
    else
        m_stability->setText(tr("UNSTABLE: max |z| = %1 at t = %2 s (growth %3 1/s)")
                                 .arg(v.worstSpectralRadius, 0, 'f', 6)
                                 .arg(v.worstTime, 0, 'f', 3)
                                 .arg(v.worstDecayRate, 0, 'g', 4));
    const int n = int(v.peakTorque.size());
    m_torques->setRowCount(n);
    for (int j = 0; j < n; ++j) {
        const double limit = j < v.torqueLimit.size() ? v.torqueLimit[j] : 0.0;
        const double use = limit > 0 ? v.peakTorque[j] / limit : 0.0;
        m_torques->setItem(j, 0, cell(QString::number(j + 1), Qt::AlignCenter));
        m_torques->setItem(j, 1, cell(QString::number(v.peakTorque[j], 'f', 3)));
        m_torques->setItem(j, 2, cell(QString::number(limit, 'f', 3)));
        auto *useCell = cell(QStringLiteral("%1 %").arg(100.0 * use, 0, 'f', 1));
        if (use > 1.0)
            useCell->setForeground(QColor(0x8c, 0x1d, 0x18));
        m_torques->setItem(j, 3, useCell);
        const double gravity = j < v.peakGravityTorque.size() ? v.peakGravityTorque[j] : 0.0;
        m_torques->setItem(
            j, 4,
            cell(QStringLiteral("%1 %").arg(limit > 0 ? 100.0 * gravity / limit : 0.0, 0, 'f', 1)));
    }
}

} // namespace learnid
