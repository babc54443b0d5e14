#include "ui/RunPanel.h"

#include "ui/ActionButton.h"

#include <QAction>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QToolButton>
#include <QVBoxLayout>

namespace learnid {

RunPanel::RunPanel(QAction *runTrial, QAction *runAll, QAction *stop, QWidget *parent)
    : QWidget(parent)
    , m_trial(new QProgressBar(this))
    , m_series(new QProgressBar(this))
    , m_status(new QLabel(this))
{
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(actionButton(runTrial, QStringLiteral("runTrialButton"), this));
    buttons->addWidget(actionButton(runAll, QStringLiteral("runAllButton"), this));
    buttons->addWidget(actionButton(stop, QStringLiteral("stopButton"), this));
    m_trial->setObjectName(QStringLiteral("trialProgress"));
    m_series->setObjectName(QStringLiteral("seriesProgress"));
    m_trial->setFormat(tr("%p %"));
    m_series->setFormat(tr("%v of %m trials"));
    m_status->setObjectName(QStringLiteral("runStatus"));
    m_status->setWordWrap(true);
    auto *form = new QFormLayout;
    form->addRow(tr("Trial:"), m_trial);
    form->addRow(tr("Series:"), m_series);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(buttons);
    layout->addLayout(form);
    layout->addWidget(m_status);
    startSeries(1);
    m_series->setValue(0);
    m_trial->setValue(0);
}

void RunPanel::startSeries(int count)
{
    m_seriesCount = std::max(1, count);
    m_series->setRange(0, m_seriesCount);
    m_series->setValue(0);
    m_trial->setRange(0, 100);
    m_trial->setValue(0);
}

void RunPanel::setTrialProgress(int trialIndex, int samplesDone, int samplesTotal)
{
    m_trial->setValue(samplesTotal > 0 ? int(100LL * samplesDone / samplesTotal) : 0);
    m_trial->setFormat(tr("trial %1: %p %").arg(trialIndex));
}

void RunPanel::trialDone(int doneInSeries)
{
    m_series->setValue(std::min(doneInSeries, m_seriesCount));
}

void RunPanel::setStatus(const QString &text)
{
    m_status->setText(text);
}

QString RunPanel::status() const
{
    return m_status->text();
}

int RunPanel::trialProgressPercent() const
{
    return m_trial->value();
}

} // namespace learnid
