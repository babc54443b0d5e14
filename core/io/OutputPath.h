#pragma once

#include <QString>

namespace learnid {

/// Resolves an output path given by a user (--report, --export, --trial-csv): relative paths
/// are taken relative to workspaceDir. The path is walked the way the OS will walk it: `..`
/// steps up from where the walk really is, and every symbolic link on the way (a dangling one
/// too, since writing through it would create its target) is replaced by its target. The part
/// that does not exist yet is taken as written.
/// Returns the resolved absolute path, which is what the caller should write to.
/// Throws Error naming `what` (e.g. "--report") and the path when the result lies outside the
/// workspace, when the workspace does not exist, or when the path is empty.
QString resolveInWorkspace(const QString &workspaceDir, const QString &path, const QString &what);

} // namespace learnid
