#include "pipeline/stages/voronoi_stage.h"

#include "core/error.h"

namespace homesh {

Stage voronoi_stage() {
  return {"voronoi",
          "new linear triangle mesh of the input's CAD, dual to the crystal Voronoi diagram",
          {{"metric", "iso", "iso | bl | FILE (coarse grid of 2x2 SPD tensors)"},
           {"seeds", "auto", "auto | FILE (one 'x y' per line)"},
           {"engine", "fast_marching", "fast_marching | level_set"},
           {"grid", "0", "grid nodes along the longer side (0 = automatic)"}},
          [](Context&, const Options&) {
            throw Error("stage 'voronoi': under construction");
          }};
}

}  // namespace homesh
