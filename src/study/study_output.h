#pragma once
// Where homesh-study writes: one folder of CSV tables and a markdown summary,
// every file written atomically (core/atomic_file.h), and the inputs every
// study part reads.
#include <string>

namespace homesh {

struct StudyInputs {
  std::string gallery;    ///< geo/gallery_t1_t12.csv
  std::string reference;  ///< the folder of the thesis tables (tests/data/thesis)
};

class StudyOutput {
 public:
  /// Creates `folder` (and its parents) if missing; throws homesh::Error if it cannot.
  explicit StudyOutput(std::string folder);

  const std::string& folder() const { return folder_; }
  /// folder/name.
  std::string path(const std::string& name) const;
  /// Writes `text` to folder/name atomically; throws homesh::Error on failure.
  void write(const std::string& name, const std::string& text) const;

 private:
  std::string folder_;
};

/// A number printed for a table: %.6g, "inf" and "nan" spelled out.
std::string number(double value);

}  // namespace homesh
