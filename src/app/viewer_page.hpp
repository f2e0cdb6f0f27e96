#pragma once
// The page `dinam view` writes (web/viewer.html, built into the program so that it needs no file
// beside it): HTML, CSS and JavaScript with three placeholders, /*DINAM_META*/, /*DINAM_FRAMES*/
// and /*DINAM_THREE*/ (three.js, app/three_module.hpp).
namespace dinam {

const char* viewer_page_template();

}  // namespace dinam
