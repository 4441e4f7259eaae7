#pragma once
// What a result file records about the build that wrote it. The definition is generated at
// build time (cmake/write_build_info.cmake), so it follows the commit without reconfiguring.

namespace rfmems {

// Short hash of the commit the library was built from, "<hash>-dirty" with uncommitted
// changes, "unknown" outside a git checkout.
const char* git_hash();

}  // namespace rfmems
