#pragma once
// The viewer's page (skeleton/app/viewer_page/), compiled into the binary
// by the build so that `pathtracer --view` works from any folder and fetches
// nothing at run time.
namespace pt {
extern const char* const kViewerHtml;  // index.html
extern const char* const kViewerJs;    // viewer.js
}  // namespace pt
