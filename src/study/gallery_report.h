#pragma once
// The gallery of thesis Fig 3.12 as data for its picture: the nodes and det J
// sampled over each element (scripts/plot_ch3.py draws the elements curved).
#include <string>

#include "study/study_output.h"

namespace homesh {

/// Writes gallery_samples.csv (columns element,order,kind,index,u,v,x,y,omega:
/// kind "node" for the nodes, "sample" for the points of the order-24 lattice
/// of the reference triangle mapped by the element, omega = det J / det J of
/// the ideal element) and returns the summary's section on the gallery.
std::string report_gallery(const StudyInputs& in, const StudyOutput& out);

}  // namespace homesh
