#include "ui/MessageBar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace learnid {

MessageBar::MessageBar(QWidget *parent)
    : QFrame(parent)
    , m_label(new QLabel(this))
    , m_close(new QToolButton(this))
{
    setObjectName(QStringLiteral("messageBar"));
    setFrameShape(QFrame::StyledPanel);
    m_label->setWordWrap(true);
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_close->setText(QStringLiteral("\u00d7"));
    m_close->setAutoRaise(true);
    m_close->setToolTip(tr("Dismiss"));
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 4, 4, 4);
    layout->addWidget(m_label, 1);
    layout->addWidget(m_close);
    connect(m_close, &QToolButton::clicked, this, &QWidget::hide);
    hide();
}

void MessageBar::showMessage(const QString &text, Severity severity)
{
    m_severity = severity;
    m_label->setText(text);
    const char *style = "";
    switch (severity) {
    case Severity::Info:
        style = "#messageBar { background: #e8f0fb; border: 1px solid #9bb7e0; }";
        break;
    case Severity::Success:
        style = "#messageBar { background: #e6f4e6; border: 1px solid #8cc48c; }";
        break;
    case Severity::Error:
        style = "#messageBar { background: #fbe9e7; border: 1px solid #e0968c; }";
        break;
    }
    setStyleSheet(QString::fromLatin1(style));
    show();
}

QString MessageBar::text() const
{
    return m_label->text();
}

} // namespace learnid
