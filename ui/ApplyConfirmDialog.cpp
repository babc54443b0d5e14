#include "ui/ApplyConfirmDialog.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace learnid {

ApplyConfirmDialog::ApplyConfirmDialog(const ApplyPreview &preview, QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("applyConfirmDialog"));
    setWindowTitle(tr("Apply parameters to the robot"));
    auto *intro = new QLabel(
        tr("Write estimate %1 to the robot controller? The controller's feedforward changes "
           "at once.")
            .arg(preview.estimateIndex),
        this);
    intro->setWordWrap(true);

    const int m = int(preview.parameters.size());
    auto *table = new QTableWidget(m, 4, this);
    table->setHorizontalHeaderLabels({tr("Parameter"), tr("On robot"), tr("New"), tr("Change")});
    table->verticalHeader()->hide();
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    for (int i = 0; i < m; ++i) {
        const ParameterInfo &p = preview.parameters.at(i);
        auto add = [&](int column, const QString &text) {
            auto *item = new QTableWidgetItem(text);
            item->setTextAlignment(column == 0 ? Qt::AlignLeft | Qt::AlignVCenter
                                               : Qt::AlignRight | Qt::AlignVCenter);
            table->setItem(i, column, item);
        };
        add(0, p.unit.isEmpty() ? p.name : QStringLiteral("%1 [%2]").arg(p.name, p.unit));
        add(1, i < preview.oldValues.size() ? QString::number(preview.oldValues[i], 'f', 4)
                                            : tr("none"));
        add(2, QString::number(preview.newValues[i], 'f', 4));
        const auto change = preview.relativeChange(i);
        add(3, change ? QString::asprintf("%+.2f %%", 100.0 * *change) : QStringLiteral("\u2013"));
    }

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    auto *apply = buttons->addButton(tr("Apply to robot"), QDialogButtonBox::AcceptRole);
    apply->setObjectName(QStringLiteral("confirmApply"));
    buttons->button(QDialogButtonBox::Cancel)->setDefault(true);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(table);
    layout->addWidget(buttons);
    resize(520, 120 + 32 * m);
}

} // namespace learnid
