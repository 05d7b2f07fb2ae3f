#include "fem/assemble_elasticity.h"

#include "fem/elasticity_assembler.h"

namespace homesh {

LinearSystem assemble_elasticity(const Mesh& m, const ElasticityCoefficients& c,
                                 const AssemblyOptions& options) {
  AssemblyOptions whole = options;
  whole.condense = false;
  const ElasticityAssembler assembler(m, {}, whole);
  EliminatedSystem lower;
  assembler.assemble(m.x, c, lower);
  LinearSystem sys;
  sys.K = lower.K.selfadjointView<Eigen::Lower>();
  sys.b = std::move(lower.load);
  return sys;
}

}  // namespace homesh
