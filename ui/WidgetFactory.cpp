#include "ui/WidgetFactory.h"

#include <QGroupBox>
#include <QPushButton>
#include <QVBoxLayout>

namespace learnid {

QPushButton *namedButton(const QString &text, const char *objectName, QWidget *parent)
{
    auto *b = new QPushButton(text, parent);
    b->setObjectName(QLatin1String(objectName));
    return b;
}

QGroupBox *titledGroup(const QString &title, QWidget *content)
{
    auto *box = new QGroupBox(title);
    auto *layout = new QVBoxLayout(box);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addWidget(content);
    return box;
}

} // namespace learnid
