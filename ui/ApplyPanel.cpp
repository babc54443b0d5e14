#include "ui/ApplyPanel.h"

#include "ui/ActionButton.h"

#include <QAction>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSpinBox>
#include <QToolButton>
#include <algorithm>

namespace learnid {

ApplyPanel::ApplyPanel(QAction *accept, QAction *apply, QAction *revert, QWidget *parent)
    : QWidget(parent)
    , m_estimate(new QSpinBox(this))
    , m_accepted(new QLabel(this))
    , m_stored(new QLabel(this))
{
    m_estimate->setObjectName(QStringLiteral("acceptIndex"));
    m_estimate->setRange(0, 0);
    m_estimate->setPrefix(tr("estimate "));
    m_stored->setWordWrap(true);
    m_accepted->setObjectName(QStringLiteral("acceptedLabel"));
    m_stored->setObjectName(QStringLiteral("storedLabel"));
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(actionButton(accept, QStringLiteral("acceptButton"), this));
    buttons->addWidget(actionButton(apply, QStringLiteral("applyButton"), this));
    buttons->addWidget(actionButton(revert, QStringLiteral("revertButton"), this));
    auto *form = new QFormLayout(this);
    form->addRow(tr("Choose:"), m_estimate);
    form->addRow(buttons);
    form->addRow(tr("Accepted:"), m_accepted);
    form->addRow(tr("Robot holds:"), m_stored);
    setAccepted(std::nullopt);
    setStored(tr("nothing applied yet"));
    connect(m_estimate, &QSpinBox::valueChanged, this,
            [this](int k) { m_followProposal = k == m_proposed; });
}

void ApplyPanel::setEstimateCount(int count, int proposed)
{
    const bool follow = m_followProposal;
    m_estimate->setRange(count > 1 ? 1 : 0, std::max(0, count - 1));
    m_proposed = proposed >= 0 ? std::clamp(proposed, m_estimate->minimum(), m_estimate->maximum())
                               : m_estimate->maximum();
    if (follow)
        m_estimate->setValue(m_proposed);
    m_followProposal = follow;
}

int ApplyPanel::chosenEstimate() const
{
    return m_estimate->value();
}

void ApplyPanel::setChosenEstimate(int k)
{
    m_estimate->setValue(k);
}

void ApplyPanel::setAccepted(std::optional<int> k)
{
    m_accepted->setText(k ? tr("estimate %1").arg(*k) : tr("none"));
}

void ApplyPanel::setStored(const QString &text)
{
    m_stored->setText(text);
}

} // namespace learnid
