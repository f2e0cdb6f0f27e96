#pragma once
// The page `dinam view` writes (web/viewer.html, built into the program so that it needs no file
// beside it): HTML, CSS and JavaScript with two placeholders, /*DINAM_META*/ and /*DINAM_FRAMES*/.
namespace dinam {

const char* viewer_page_template();

}  // namespace dinam
