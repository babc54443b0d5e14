#pragma once

#include <QString>

namespace learnid::bench {

/// The GUI targets for a 7-axis arm (issue: any serial arm): the update of plots, table and chart
/// after each of 10 trials of the built-in robot's default scenario and, after trial 10, over
/// `repetitions`; then the GUI thread's largest gap between timer ticks while the window's
/// SessionController runs 10 trials, in `sessions` fresh windows. Prints Markdown.
void serialArmGui(const QString &modelId, int repetitions, int sessions);

} // namespace learnid::bench
