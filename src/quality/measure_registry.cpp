#include "quality/measure_registry.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "quality/branets_carey_measures.h"
#include "quality/jacobian_variation.h"
#include "quality/shape_measures.h"
#include "quality/size_measures.h"
#include "quality/volume_measures.h"

namespace homesh {
namespace {

constexpr Invariance kScaleInvariant{true, true, true};
constexpr Invariance kScaleSensitive{true, false, true};

std::vector<Measure> make_measures() {
  const auto q14_raw = [](const Eigen::Matrix2d& W) { return shape_dilation_raw(W); };
  const auto q14 = [](const Eigen::Matrix2d& W) { return shape_dilation_quality(W); };
  return {
      {"Q1", "Variation of J", "min J / max J over the element", "none: in [0, 1]; 0 if min J <= 0",
       "Eq 3.33; Dey et al. [66]", kScaleInvariant, false, idealised_jacobian_raw, nullptr,
       jacobian_variation},
      {"Q2", "Laplace", "|W|_F^2", "min(x, 1/x), x = |W|_F^2 / 2", "Eq 3.34; Knupp 2001 [59]",
       kScaleSensitive, true, laplace_raw, laplace_quality, nullptr},
      {"Q3", "Metric tensor", "|W^T W|_F^2", "min(x, 1/x), x = |D|_F^2 / 2",
       "Eq 3.37; Liao [21], Knupp 2001 [59]", kScaleSensitive, true, metric_tensor_raw,
       metric_tensor_quality, nullptr},
      {"Q4", "Equal volume", "omega^2", "min(omega^2, 1/omega^2)",
       "Eq 3.38; Knupp 2001 [59] after [13]", kScaleSensitive, true, equal_volume_raw,
       equal_volume_quality, nullptr},
      {"Q5", "Adjoint matrix", "|adj W|_F^2", "min(x, 1/x), x = |adj W|_F^2 / 2",
       "Eq 3.39; Jacquotte & Cabello [50]", kScaleSensitive, true, adjoint_raw, adjoint_quality,
       nullptr},
      {"Q6", "Smoothness", "(omega |W^-1|_F^2)^-1", "2 raw", "Eq 3.40; Brackbill & Saltzman [29]",
       kScaleInvariant, false, smoothness_raw, smoothness_quality, nullptr},
      {"Q7", "Aspect ratio", "(|W|_F^2 / omega)^-1", "2 raw",
       "Eq 3.41; Tinoco-Ruiz & Barrera-Sanchez [38, 39]", kScaleInvariant, false, aspect_ratio_raw,
       aspect_ratio_quality, nullptr},
      {"Q8", "Shape", "[3/2 omega^(-4/d) (|W^T W|_F^2 - 1/3 |W|_F^4)]^-1, d = 2",
       "none: raw in (0, 1]", "Eq 3.42; Oddy et al. [6], Knupp 2001 [59]", kScaleInvariant, false,
       oddy_raw, oddy_quality, nullptr},
      {"Q9", "Non-dimensional smoothness", "(omega^(2/3) |W^-1|_F^2)^-1", "min(x, 1/x), x = 2 raw",
       "Eq 3.43; Knupp 2001 [59]", kScaleSensitive, false, nondimensional_smoothness_raw,
       nondimensional_smoothness_quality, nullptr},
      {"Q10", "Inverse mean ratio", "(omega^(-2/3) |W|_F^2)^-1", "min(x, 1/x), x = 2 raw",
       "Eq 3.43; Liu & Joe [5], Knupp [51]", kScaleSensitive, false, inverse_mean_ratio_raw,
       inverse_mean_ratio_quality, nullptr},
      {"Q11", "Condition number of W", "(|W|_F |W^-1|_F)^-1", "2 raw",
       "Eq 3.44; Freitag & Knupp [46, 52]", kScaleInvariant, false, condition_number_raw,
       condition_number_quality, nullptr},
      {"Q12", "Shape quality", "([tr(W^T W) / d]^(d/2) / omega)^-1, d = 2", "none: raw in (0, 1]",
       "Eq 3.45; Branets & Carey [42, 43, 44]", kScaleInvariant, false, shape_raw, shape_quality,
       nullptr},
      {"Q13", "Dilation", "[1/2 (V / omega + omega / V)]^-1, V = 1", "none: raw in (0, 1]",
       "Eq 3.45; Branets & Carey [42, 43, 44]", kScaleSensitive, false, dilation_raw,
       dilation_quality, nullptr},
      {"Q14", "Shape quality & dilation", "[(1 - alpha) / Q12 + alpha / Q13]^-1, alpha = 1/2",
       "none: raw in (0, 1]", "Eq 3.45; Branets & Carey [42, 43, 44]", kScaleSensitive, false,
       q14_raw, q14, nullptr},
      {"Q16", "Condition number of D", "(|D|_F |D^-1|_F)^-1, D = W^T W", "2 raw",
       "Eq 3.44; Freitag & Knupp [51]", kScaleInvariant, false, metric_condition_number_raw,
       metric_condition_number_quality, nullptr},
      {"Q17", "Idealised Jacobian", "omega = det W", "min(omega, 1/omega)", "Eq 3.47",
       kScaleSensitive, true, idealised_jacobian_raw, idealised_jacobian_quality, nullptr},
  };
}

// The 3D forms (d = 3) of the pointwise measures, by name.
std::vector<Measure> with_volume_forms(std::vector<Measure> table) {
  const struct {
    const char* name;
    PointMeasure3 raw, quality;
  } forms[] = {
      {"Q2", laplace_raw3, laplace_quality3},
      {"Q3", metric_tensor_raw3, metric_tensor_quality3},
      {"Q4", equal_volume_raw3, equal_volume_quality3},
      {"Q5", adjoint_raw3, adjoint_quality3},
      {"Q6", smoothness_raw3, smoothness_quality3},
      {"Q7", aspect_ratio_raw3, aspect_ratio_quality3},
      {"Q8", oddy_raw3, oddy_quality3},
      {"Q9", nondimensional_smoothness_raw3, nondimensional_smoothness_quality3},
      {"Q10", inverse_mean_ratio_raw3, inverse_mean_ratio_quality3},
      {"Q11", condition_number_raw3, condition_number_quality3},
      {"Q12", shape_raw3, shape_quality3},
      {"Q13", dilation_raw3, dilation_quality3},
      {"Q14", shape_dilation_raw3, shape_dilation_quality3},
      {"Q16", metric_condition_number_raw3, metric_condition_number_quality3},
      {"Q17", idealised_jacobian_raw3, idealised_jacobian_quality3},
  };
  for (Measure& m : table)
    for (const auto& f : forms)
      if (m.name == f.name) {
        m.raw3 = f.raw;
        m.quality3 = f.quality;
      }
  return table;
}

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

}  // namespace

const std::vector<Measure>& measures() {
  static const std::vector<Measure> table = with_volume_forms(make_measures());
  return table;
}

std::string element_field_name(const Measure& q) {
  return "homesh: " + q.name + " " + q.title + ", element minimum";
}

std::string node_field_name(const Measure& q) {
  return "homesh: " + q.name + " " + q.title + ", at nodes";
}

const Measure& measure(const std::string& name) {
  const std::string key = upper(name);
  for (const Measure& m : measures()) {
    if (m.name == key) return m;
  }
  std::string valid;
  for (const Measure& m : measures()) valid += (valid.empty() ? "" : ", ") + m.name;
  std::string message = "unknown quality measure '" + name + "'; valid measures: " + valid;
  if (key == "Q15") {
    message +=
        " (Q15, Salem et al., is not implemented: the thesis does not define its parameters "
        "gamma_min and gamma_max and excludes it from every assessment)";
  }
  throw Error(message);
}

}  // namespace homesh
