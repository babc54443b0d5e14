#pragma once

#include "session/EstimateConsistency.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace learnid {

class ChainModel;

/// The verdict on each link of identified standard parameters as a table, worded once for
/// `learnid-cli identify` (its text and PDF report) and the window's "Identify from recorded
/// data": per link its number and name, the smallest principal moment of inertia about its
/// centre of mass and the CAD link's, (I1 + I2) / I3, whether the centre of mass lies inside the
/// link's bounding volume, and whether the link is physically consistent (a real body) and
/// plausible (a body a robot's link could be; docs/robots.md §6).
struct LinkVerdictTable
{
    QString title;           ///< a sentence saying what the columns mean (long: wrap it to show it)
    QStringList header;      ///< the column titles
    QList<QStringList> rows; ///< per link, its cells (as many as header)
    QList<bool> plausible;   ///< per row: the link consistent and plausible
};

/// The table of verdict's links (EstimateConsistency::plausibility and links, chain order) for
/// model's chain. Cells a link cannot have (no positive mass, no volume) read "-". Empty rows
/// when the verdict is not applicable.
LinkVerdictTable linkVerdictTable(const ChainModel &model, const EstimateConsistency &verdict);

/// The header and a row per link as fixed-width text (without the title), each line ended by a
/// newline; the first column left-aligned, the others right-aligned under their titles.
QString linkVerdictText(const LinkVerdictTable &table);

} // namespace learnid
