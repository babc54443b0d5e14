#include "ui/ApplyPreview.h"

#include <cmath>

namespace learnid {

std::optional<double> ApplyPreview::relativeChange(int i) const
{
    if (i < 0 || i >= oldValues.size() || i >= newValues.size() || oldValues[i] == 0.0)
        return std::nullopt;
    return (newValues[i] - oldValues[i]) / std::abs(oldValues[i]);
}

} // namespace learnid
