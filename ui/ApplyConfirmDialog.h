#pragma once

#include "ui/ApplyPreview.h"

#include <QDialog>

namespace learnid {

/// Asks before parameters are written to the robot: old against new values with the relative
/// change of each. Accepted means "write them".
class ApplyConfirmDialog : public QDialog
{
    Q_OBJECT

public:
    explicit ApplyConfirmDialog(const ApplyPreview &preview, QWidget *parent = nullptr);
};

} // namespace learnid
