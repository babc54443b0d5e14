#pragma once

#include <QString>

namespace learnid {

/// The absolute path of an output a user named (--report, --export, --trial-csv, --can-log):
/// relative paths are taken relative to baseDir (learnid-cli's --workspace, default the current
/// directory), absolute ones as given. Anywhere the user may write is allowed: the path is the
/// user's choice; the writers keep every write atomic and all-or-nothing. The path is not cleaned
/// lexically ("link/.." is left for the operating system to walk, as the user's shell would).
/// Throws Error naming `what` (e.g. "--report") for an empty path, or a relative one when baseDir
/// does not exist or is not a folder.
QString resolveOutputPath(const QString &baseDir, const QString &path, const QString &what);

} // namespace learnid
