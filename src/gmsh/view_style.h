#pragma once
// How homesh's views look in Gmsh: one certified minJ/maxJ view shown, on a
// fixed [0, 1] range, curved; every other view present but hidden. The style
// lives in each view's own Gmsh options (View[i].*), set when the view is
// added, so a program that calls gmsh.fltk.run() after homesh sees what a user
// who opens the written file sees: the file's sidecar `.opt` is written from
// the same options (sidecar_options).
#include <string>
#include <vector>

#include "core/field.h"

namespace homesh::gmsh_adapter {

/// The View options homesh styles (and writes to the sidecar), e.g.
/// "Visible", "RangeType", "AdaptVisualizationGrid".
const std::vector<std::string>& styled_view_options();

/// Styles the view `view_tag` holding `field` on elements of order `order`:
/// - drawn curved and crack-free: AdaptVisualizationGrid 1 with TargetError -1,
///   which makes Gmsh refine every element uniformly to MaxRecursionLevel
///   (with a positive TargetError Gmsh refines only where the values vary, so
///   an element-constant field is drawn on the straight triangle);
/// - a quality (field.quality): fixed range [0, 1], values below saturated to
///   0, so invalid elements are black, poor ones dark purple to red, good ones
///   orange to pale yellow (Gmsh's colormap 21, inferno); element-constant
///   fields in ten discrete bands, fields at nodes continuous;
/// - visible with its colour scale if field.shown, hidden otherwise;
/// - points and lines of element data not drawn (they carry a neutral value).
void style_view(int view_tag, const Field& field, int order);

/// Makes Gmsh draw high-order mesh edges curved (Mesh.NumSubEdges, raised to
/// the sidecar's value if lower), as opening a homesh file does.
void draw_edges_curved();

/// Hides every view but `view_tags`: the views just added are the ones shown.
void hide_other_views(const std::vector<int>& view_tags);

/// The sidecar text for a file holding `view_tags` (in this order, the last
/// views Gmsh reads from it): each view's styled options as they are now in
/// Gmsh, addressed relative to the number of views loaded
/// (View[PostProcessing.NbViews - n + i]), as Gmsh merges FILE.opt right
/// after reading FILE; the views loaded before are hidden, so one colour scale
/// shows however many files are merged. Needs an initialized Gmsh.
std::string sidecar_options(const std::vector<int>& view_tags);

}  // namespace homesh::gmsh_adapter
