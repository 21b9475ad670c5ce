// SPDX-License-Identifier: Apache-2.0
// Atomic file replacement for everything the user saves from the teach code (programs, reports):
// write a temporary file in the same folder, fsync it, rename it over the target, fsync the folder.
#pragma once

#include <string>

namespace xmate::teach {

// Replaces `path` with `contents`. On any failure the previous file is untouched, the temporary is
// removed, and std::runtime_error says what failed (with the OS reason) and what to do. The new
// file keeps the permissions of the one it replaces; a symbolic link at `path` stays a link and
// the file it points to is replaced.
void writeFileAtomically(const std::string& path, const std::string& contents);

// The whole file; std::runtime_error naming the path and the OS reason if it cannot be read.
std::string readFile(const std::string& path);

}  // namespace xmate::teach
