#pragma once
/// The renderer (OSMesa and with it LLVM, FreeType, libpng: tens of MB to map) is a plugin,
/// libcogmap_render_plugin.so, loaded on the first figure: a process that draws nothing never
/// maps it. The writers of figures.h load it themselves; require_renderer() lets a command fail
/// before it starts work that would end in a figure.

#include <stdexcept>

namespace cogmap::render {

/// The plugin cannot be loaded (missing, unreadable, from another build). The message names
/// the file, the loader's reason and what to do.
class RendererUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Loads the plugin now, once per process (thread-safe); throws RendererUnavailable. Looks in
/// $COGMAP_PLUGIN_DIR when set, else on the program's run path: lib/cogmap beside the installed
/// bin/, or the build tree's lib/cogmap.
void require_renderer();

/// Makes the rasteriser (Mesa's llvmpipe) draw on each drawing thread alone instead of starting
/// helper threads of its own, one per core. For a process whose own threads already keep every
/// core busy (a sweep running a job per core): the helpers would only take turns with the runs
/// (docs/performance.md, "Sweeps on two cores"). It sets LP_NUM_THREADS=0, which Mesa reads when
/// the first figure starts the rasteriser, so call it before the first figure and before the
/// process starts threads of its own (setenv is not thread-safe). A value the user has set is
/// kept. Returns whether it set the value.
bool rasterise_on_drawing_threads_only();

}  // namespace cogmap::render
