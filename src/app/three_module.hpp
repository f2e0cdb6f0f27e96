#pragma once
// three.js (three.module.min.js, the version web/package-lock.json pins), built into the program
// from web/node_modules (src/app/CMakeLists.txt), for the page `dinam view` writes: the program
// never fetches it.

namespace dinam {

const char* three_module_source();

}  // namespace dinam
