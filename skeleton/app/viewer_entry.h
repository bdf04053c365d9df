#pragma once
// How the command line reaches the viewer without depending on it: the
// viewer's object library (pt_viewer) sets this when it is linked in, and
// `--view` in a binary without it says so instead of failing to link.
namespace pt {

class Scene;
struct ViewerOptions;

using ViewerEntry = int (*)(Scene& scene, const ViewerOptions& options);
// The viewer's entry point; null when the binary has no viewer.
ViewerEntry& viewer_entry();

}  // namespace pt
