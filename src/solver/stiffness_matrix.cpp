#include "solver/stiffness_matrix.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cstdint>

#include "core/error.hpp"
#include "dynamics/contact/ground_contact.hpp"
#include "dynamics/contact/object_contact.hpp"
#include "dynamics/force_kinds.hpp"
#include "dynamics/spring_kinds.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// An element's matrix with its negative eigenvalues set to zero: V max(Λ, 0) Vᵀ.
template <int kSize>
void project_to_semidefinite(double* stiffness) {
  using Matrix = Eigen::Matrix<double, kSize, kSize>;
  Eigen::Map<Matrix> k(stiffness);
  const Eigen::SelfAdjointEigenSolver<Matrix> eigen(k);
  if (eigen.eigenvalues().minCoeff() >= 0.0) {
    return;
  }
  k = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
      eigen.eigenvectors().transpose();
}

// An element's matrix as the assembly takes it, in place: made positive semi-definite where asked.
void prepare_element(int node_count, Definiteness definiteness, double* stiffness) {
  if (definiteness == Definiteness::kExact) {
    return;
  }
  switch (node_count) {
    case 1:
      project_to_semidefinite<3>(stiffness);
      break;
    case 2:
      project_to_semidefinite<6>(stiffness);
      break;
    case 3:
      project_to_semidefinite<9>(stiffness);
      break;
    case 4:
      project_to_semidefinite<12>(stiffness);
      break;
    default:
      DINAM_CHECK(false);
  }
}

// Calls block(row_dof, col_dof, columns, stride) for each 3 × 3 block of an element's matrix
// (`matrix`, 3 node_count square, column-major) between two free nodes: the block's column b
// holds row_dof's x, y and z at columns + b stride, for col_dof + b. Stops where it returns false.
template <class Block>
void for_each_block(const FreeDofs& dofs, const Index* nodes, int node_count, const double* matrix,
                    const Block& block) {
  const std::size_t size = 3 * static_cast<std::size_t>(node_count);
  for (int col_node = 0; col_node < node_count; ++col_node) {
    const Index col_dof = dofs.first_dof[nodes[col_node]];
    if (col_dof < 0) {
      continue;
    }
    for (int row_node = 0; row_node < node_count; ++row_node) {
      const Index row_dof = dofs.first_dof[nodes[row_node]];
      if (row_dof < 0) {
        continue;
      }
      const std::size_t at = 3 * static_cast<std::size_t>(col_node) * size + 3 * row_node;
      if (!block(row_dof, col_dof, &matrix[at], size)) {
        return;
      }
    }
  }
}

// Gathers the 3 × 3 blocks between free nodes that an assembly would hand over, by where each
// starts (its column's and its row's first degree of freedom), without their values: the pattern
// the values are then added into. A block is 8 bytes here where its nine triplets took 144, which
// on a cloth of 10 000 nodes was 130 MB, a third of an implicit run's memory.
class BlockPatternSink final : public StiffnessSink {
 public:
  BlockPatternSink(const FreeDofs& dofs, std::vector<std::uint64_t>& blocks)
      : dofs_(dofs), blocks_(blocks) {}

  static std::uint64_t key(Index col_dof, Index row_dof) {
    return (static_cast<std::uint64_t>(col_dof) << 32) | static_cast<std::uint32_t>(row_dof);
  }

  void prepare(int /*node_count*/, double* /*stiffness*/) const override {}  // values unread

  void add_prepared(const Index* nodes, int node_count, const double* stiffness) override {
    for_each_block(dofs_, nodes, node_count, stiffness,
                   [&](Index row_dof, Index col_dof, const double*, std::size_t) {
                     blocks_.push_back(key(col_dof, row_dof));
                     return true;
                   });
  }

 private:
  const FreeDofs& dofs_;
  std::vector<std::uint64_t>& blocks_;
};

// Adds each element's 3 × 3 blocks between free nodes into the values of a matrix whose pattern
// holds them already (that of an earlier assembly), without the triplets' sort; notes where a
// block is not in the pattern (a pair of objects that was not touching before).
class PatternSink final : public StiffnessSink {
 public:
  PatternSink(const FreeDofs& dofs, Definiteness definiteness, SparseMatrix& matrix)
      : dofs_(dofs), definiteness_(definiteness), matrix_(matrix) {}

  bool missed() const { return missed_; }

  void prepare(int node_count, double* stiffness) const override {
    prepare_element(node_count, definiteness_, stiffness);
  }

  void add_prepared(const Index* nodes, int node_count, const double* stiffness) override {
    if (missed_) {
      return;
    }
    const int* outer = matrix_.outerIndexPtr();
    const int* inner = matrix_.innerIndexPtr();
    double* matrix_values = matrix_.valuePtr();
    // Whether column `column` holds `row` at its entry `place`, with the block's three rows there.
    auto holds = [&](Index column, std::ptrdiff_t place, Index row) {
      return place >= 0 && outer[column + 1] - outer[column] - place >= 3 &&
             inner[outer[column] + place] == row;
    };
    for_each_block(dofs_, nodes, node_count, stiffness,
                   [&](Index row_dof, Index col_dof, const double* columns, std::size_t stride) {
                     // Every block of the pattern came in whole (explicit zeros included), so a
                     // node's three columns hold the same rows: one search in the first finds the
                     // block's place in all three (checked, since a miss means a new pattern).
                     const int* first = inner + outer[col_dof];
                     const int* last = inner + outer[col_dof + 1];
                     const std::ptrdiff_t place =
                         std::lower_bound(first, last, static_cast<int>(row_dof)) - first;
                     if (!holds(col_dof, place, row_dof) || !holds(col_dof + 1, place, row_dof) ||
                         !holds(col_dof + 2, place, row_dof)) {
                       missed_ = true;
                       return false;
                     }
                     for (int b = 0; b < 3; ++b) {
                       double* column_values = matrix_values + outer[col_dof + b] + place;
                       for (int a = 0; a < 3; ++a) {
                         column_values[a] += columns[b * stride + a];
                       }
                     }
                     return true;
                   });
  }

 private:
  const FreeDofs& dofs_;
  Definiteness definiteness_;
  SparseMatrix& matrix_;
  bool missed_ = false;
};

// Adds the trace of each element's 3 × 3 blocks between free nodes, after the element's matrix is
// made positive semi-definite, as a triplet over the free nodes.
class TraceSink final : public StiffnessSink {
 public:
  TraceSink(const FreeDofs& dofs, std::vector<Eigen::Triplet<double>>& traces)
      : dofs_(dofs), traces_(traces) {}

  void prepare(int node_count, double* stiffness) const override {
    prepare_element(node_count, Definiteness::kProjected, stiffness);
  }

  void add_prepared(const Index* nodes, int node_count, const double* stiffness) override {
    for_each_block(dofs_, nodes, node_count, stiffness,
                   [&](Index row_dof, Index col_dof, const double* columns, std::size_t stride) {
                     const double trace =
                         columns[0] + columns[stride + 1] + columns[2 * stride + 2];
                     if (trace != 0.0) {
                       traces_.emplace_back(row_dof / 3, col_dof / 3, trace);
                     }
                     return true;
                   });
  }

 private:
  const FreeDofs& dofs_;
  std::vector<Eigen::Triplet<double>>& traces_;
};

// Hands every element of the kinds `switches` leaves on to `sink`.
void add_elements(const Model& model, const State& state, const ForceSwitches& switches,
                  StiffnessSink& sink) {
  for (const ForceKind* kind : kForceKinds) {
    if (kind->add_stiffness != nullptr && switches.*kind->switched) {
      kind->add_stiffness(model, state, sink);
    }
  }
}

}  // namespace

const SparseMatrix& StiffnessAssembly::assemble(const Model& model, const State& state,
                                                const ForceSwitches& switches, const FreeDofs& dofs,
                                                Definiteness definiteness) {
  // Into the pattern of the last assembly where it holds every block.
  if (matrix_.rows() == dofs.count && matrix_.nonZeros() > 0) {
    std::fill_n(matrix_.valuePtr(), matrix_.nonZeros(), 0.0);
    PatternSink sink(dofs, definiteness, matrix_);
    add_elements(model, state, switches, sink);
    if (!sink.missed()) {
      return matrix_;
    }
  }
  // Every node held: nothing to assemble (nor to compress: Eigen's compression of a matrix without
  // columns reads past them).
  if (dofs.count == 0) {
    matrix_.resize(0, 0);
    return matrix_;
  }
  // A new pattern: every free node's diagonal block (so that the pattern does not change with the
  // ground) and every block the elements hand over, each once; then the values into it.
  blocks_.clear();
  for (Index i = 0; i < model.node_count(); ++i) {
    const Index dof = dofs.first_dof[i];
    if (dof >= 0) {
      blocks_.push_back(BlockPatternSink::key(dof, dof));
    }
  }
  BlockPatternSink pattern(dofs, blocks_);
  add_elements(model, state, switches, pattern);
  std::sort(blocks_.begin(), blocks_.end());
  blocks_.erase(std::unique(blocks_.begin(), blocks_.end()), blocks_.end());
  Eigen::VectorXi column_sizes = Eigen::VectorXi::Zero(dofs.count);
  for (const std::uint64_t block : blocks_) {
    column_sizes.segment<3>(static_cast<Index>(block >> 32)).array() += 3;
  }
  matrix_ = SparseMatrix(dofs.count, dofs.count);
  matrix_.reserve(column_sizes);
  for (const std::uint64_t block : blocks_) {  // by column, then row: each column filled in order
    const auto col_dof = static_cast<Index>(block >> 32);
    const auto row_dof = static_cast<Index>(block & 0xffffffffU);
    for (int b = 0; b < 3; ++b) {
      for (int a = 0; a < 3; ++a) {
        matrix_.insert(row_dof + a, col_dof + b) = 0.0;
      }
    }
  }
  matrix_.makeCompressed();
  blocks_ = {};  // the pattern is kept in matrix_: its blocks' list is not
  PatternSink sink(dofs, definiteness, matrix_);
  add_elements(model, state, switches, sink);
  DINAM_CHECK(!sink.missed());
  return matrix_;
}

void add_block_traces(const Model& model, const State& state, const ForceSwitches& switches,
                      const FreeDofs& dofs, std::vector<Eigen::Triplet<double>>& traces) {
  TraceSink sink(dofs, traces);
  add_elements(model, state, switches, sink);
}

}  // namespace dinam
