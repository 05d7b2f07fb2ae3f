#include "study/representation_report.h"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "element/reference_nodes.h"
#include "optim/distortion_representation.h"
#include "quality/element_sampling.h"

namespace homesh {
namespace {

const char* kThesisTable = "table_3_2_distortion_representation.csv";

std::string tick(bool b) { return b ? "1" : "0"; }

// A measure that sees only the size of W (its quality is 1 under a shear at
// unit area): Q4, Q13, Q17 with the pointwise normalisation.
bool size_only(const Measure& m) {
  Eigen::Matrix2d shear;
  shear << 1.0, 0.5, 0.0, 1.0;
  return m.pointwise() && m.quality(shear) == 1.0;
}

// omega = det W on the criterion's sample points of e: (min, max).
std::pair<double, double> area_ratio_range(const GalleryElement& e, int lattice) {
  const ElementSampling s(e.order, reference_nodes(lattice));
  double lo = 1e300, hi = -1e300;
  for (int k = 0; k < s.size(); ++k) {
    const double omega = s.jacobian(e.nodes, k).determinant() / (std::sqrt(3.0) / 2.0);
    lo = std::min(lo, omega);
    hi = std::max(hi, omega);
  }
  return {lo, hi};
}

std::string explain(const RepresentationCell& c, const GalleryElement& e,
                    const RepresentationCriterion& crit) {
  std::string why;
  if (!c.represents) {
    if (!c.distorted)
      why += fmt::format("detects a distortion of the ideal element (f = {:.3g}). ", c.f);
    if (c.distorted && !c.detected) {
      why += fmt::format("Not detected: f = {:.3g} <= {}. ", c.f, crit.detection);
    }
    if (c.detected && !c.distributes) {
      why += "Theta is constant over an element whose W varies: no distribution. ";
    }
    if (c.detected && c.distributes && c.inverted) {
      why += fmt::format(
          "Inverted: rho(Theta, H) = {:.2f} <= -{}: the measure rates the most strained points "
          "of our {} as its best ones (with Q / Qmax the point of largest raw value is called "
          "perfect). ",
          c.correlation, crit.inversion, e.name);
    }
    return why;
  }
  why += fmt::format(
      "Passes every test: f = {:.3g} > {}, Theta varies, rho(Theta, H) = {:.2f} > -{}. ", c.f,
      crit.detection, c.correlation, crit.inversion);
  if (size_only(measure(c.measure))) {
    const auto [lo, hi] = area_ratio_range(e, crit.lattice_order);
    why += fmt::format(
        "{} sees only the area ratio omega = det W against the unit ideal; our {} changes the "
        "area (omega from {:.2f} to {:.2f} on the samples), so any size measure sees it: the "
        "thesis's {} must have kept the area close to the ideal one. ",
        c.measure, e.name, lo, hi, e.name);
  } else if (std::abs(c.correlation) < crit.inversion) {
    why += fmt::format(
        "Its distribution is only weakly tied to the strain (|rho| = {:.2f} < {}): partly "
        "misplaced, which the thesis's eye judged a failure and our inversion test does not. ",
        std::abs(c.correlation), crit.inversion);
  }
  return why;
}

}  // namespace

std::string report_representation(const StudyInputs& in, const StudyOutput& out) {
  const std::vector<GalleryElement> gallery = read_gallery(in.gallery);
  const ThesisTable thesis = read_thesis_table(in.reference + "/" + kThesisTable);
  const RepresentationCriterion crit;
  const std::vector<RepresentationCell> cells = distortion_representation(gallery, crit);
  const TableAgreement full = compare_with_thesis(cells, thesis);
  const TableAgreement detect = compare_with_thesis(cells, thesis, &RepresentationCell::detects);
  const TableAgreement distribute =
      compare_with_thesis(cells, thesis, &RepresentationCell::detects_and_distributes);

  std::string ours = fmt::format(
      "# Table 3.2 reproduced by homesh-study on {}: can measure Qk represent the distortion of "
      "Tn? (1 = yes)\n# Criterion: table_3_2_note.md. Agreement with the thesis: {}/{} cells.\n"
      "measure",
      in.gallery, full.agree, full.compared);
  for (const GalleryElement& e : gallery) ours += "," + e.name;
  ours += "\n";
  std::string long_csv =
      "measure,element,thesis,ours,agree,f,rho,detected,distributes,inverted,"
      "ours_detection_only,ours_detection_and_distribution\n";
  std::string md_table = "| measure |";
  for (const GalleryElement& e : gallery) md_table += " " + e.name + " |";
  md_table += "\n|---|";
  for (size_t i = 0; i < gallery.size(); ++i) md_table += "---|";
  md_table += "\n";
  for (size_t i = 0; i < cells.size(); ++i) {
    const RepresentationCell& c = cells[i];
    const bool first = i % gallery.size() == 0;
    if (first) {
      ours += c.measure;
      md_table += "| " + c.measure + " |";
    }
    const bool listed = thesis.has(c.measure, c.element);
    const std::string t = listed ? thesis.at(c.measure, c.element) : "";
    ours += "," + tick(c.represents);
    md_table += " " + tick(c.represents) + (listed && t != tick(c.represents) ? "*" : "") + " |";
    long_csv +=
        fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}\n", c.measure, c.element, t,
                    tick(c.represents), listed ? tick(t == tick(c.represents)) : "", number(c.f),
                    number(c.correlation), tick(c.detected), tick(c.distributes), tick(c.inverted),
                    tick(c.detects), tick(c.detects_and_distributes));
    if ((i + 1) % gallery.size() == 0) {
      ours += "\n";
      md_table += "\n";
    }
  }
  out.write("table_3_2_ours.csv", ours);
  out.write("table_3_2_cells.csv", long_csv);

  std::string note = fmt::format(
      "# Table 3.2 (distortion representation): our criterion and the thesis\n\n"
      "Thesis: `{}/{}`. Ours: `table_3_2_ours.csv`, numbers in `table_3_2_cells.csv`. "
      "Gallery: `{}`.\n\n"
      "## Criterion\n\n"
      "Qk represents the distortion of Tn when (Theta = 1/Q - 1, Eq 3.49, with the thesis's "
      "Q / Qmax normalisation of Q1-Q5 and Q17; samples: the order-{} lattice, {} points):\n\n"
      "1. it **detects** it: the element distortion function f (Eq 3.48, r = {}, Gauss rule of "
      "degree {}) exceeds {};\n"
      "2. it **distributes** it: where W varies over the element, Theta varies over the samples "
      "(the thesis: Q1 \"does not display this as a varying distribution over each element\");\n"
      "3. it is **not inverted**: Spearman's rho between Theta and the Hencky strain "
      "H = sqrt(log^2 s1 + log^2 s2) of W (s1, s2 its singular values: the measure-free "
      "logarithmic distance of W from the rotations, 0 only where the element is locally the "
      "ideal one) is above -{} (the thesis: Q2, Q3, Q5 give \"inappropriate results\").\n\n"
      "An ideal element (T1) is represented when nothing is detected. Tests 2 and 3 are void "
      "on an affine element (T2).\n\n"
      "## Agreement with the thesis\n\n"
      "| criterion | agreeing cells |\n|---|---|\n"
      "| 1 (detection only) | {}/{} |\n| 1 + 2 | {}/{} |\n| 1 + 2 + 3 (ours) | {}/{} |\n\n"
      "## Disagreements ({})\n\n",
      in.reference, kThesisTable, in.gallery, crit.lattice_order,
      (crit.lattice_order + 1) * (crit.lattice_order + 2) / 2, crit.distortion.r,
      crit.distortion.quadrature_degree, crit.detection, crit.inversion, detect.agree,
      detect.compared, distribute.agree, distribute.compared, full.agree, full.compared,
      full.disagreements.size());
  for (const RepresentationCell* c : full.disagreements) {
    note += fmt::format("- **{} on {}** (thesis {}, ours {}): {}\n", c->measure, c->element,
                        thesis.at(c->measure, c->element), tick(c->represents),
                        explain(*c, gallery_element(gallery, c->element), crit));
  }
  out.write("table_3_2_note.md", note);

  return fmt::format(
      "## Table 3.2: distortion representation (Section 3.7.3)\n\n"
      "Agreement with the thesis: **{}/{} cells** by our criterion (detection only: {}/{}; "
      "detection and distribution: {}/{}). Criterion and every disagreement explained in "
      "`table_3_2_note.md`. Ours (* = differs from the thesis):\n\n{}\n",
      full.agree, full.compared, detect.agree, detect.compared, distribute.agree,
      distribute.compared, md_table);
}

}  // namespace homesh
