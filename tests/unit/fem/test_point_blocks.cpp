// An element's large products taken by blocks of quadrature points (fem/point_blocks.hpp): the
// blocks cover every point once, in order; a high-degree element's stiffness by blocks is the
// sum over all its points; a stop request is honoured between blocks.
#include <gtest/gtest.h>

#include <csignal>
#include <vector>

#include "fem_test_meshes.hpp"
#include "hpcontact/core/stop.hpp"
#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/fem/elasticity.hpp"
#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/fem/finite_strain.hpp"
#include "hpcontact/fem/point_blocks.hpp"
#include "hpcontact/mesh/element_map.hpp"

using namespace hpcontact;

// Consecutive blocks from 0 to n, none empty, each within its share of work (at least 8
// points); an element of little work is one block.
TEST(PointBlocks, CoverEveryPointOnceInOrder) {
  for (const int n : {0, 1, 7, 8, 9, 100, 441, 3721})
    for (const double flops : {1.0, 1e5, 1.2e6, 1e9}) {
      int next = 0, blocks = 0;
      fem::for_point_blocks(n, flops, [&](int first, int count) {
        EXPECT_EQ(first, next);
        EXPECT_GT(count, 0);
        EXPECT_LE(count, std::max(8.0, (1 << 28) / flops));
        next = first + count;
        ++blocks;
      });
      EXPECT_EQ(next, n) << n << " points, " << flops;
      if (n * flops <= (1 << 28)) EXPECT_LE(blocks, 1);
    }
}

namespace {

struct HighDegree {
  mesh::Mesh mesh = fem_test::sector_quad();
  fem::DofMap dofs;
  fem::ElementValues ev;
  explicit HighDegree(int p)
      : dofs(mesh, [p] {
          fem::SpaceOptions o;
          o.degrees = {{p, p}};
          return o;
        }()),
        ev(fem::element_values(dofs.element(0), mesh::ElementMap::blending(mesh, 0), p + 2, mesh,
                               0)) {}
};

material::LinearElastic steel() {
  material::LinearElastic m;
  m.youngs_modulus = 210000;
  m.poisson_ratio = 0.3;
  return m;
}

}  // namespace

// At p = 18 (400 points, two blocks) the stiffness by blocks is Σ_k w_k B_kᵀ D B_k over every
// point, B_k stacked for all points in one product; and the finite-strain tangent at rest,
// blocked otherwise (its products are larger), is the same matrix.
TEST(PointBlocks, HighDegreeStiffnessIsTheSumOverEveryPoint) {
  const HighDegree e(18);
  const int n = e.ev.n_modes(), nq = e.ev.n_points();
  int blocks = 0;
  fem::for_point_blocks(nq, 6.0 * n * n, [&](int, int) { ++blocks; });
  ASSERT_GE(blocks, 2);
  const material::Elasticity D = steel().D();
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(3 * nq, 2 * n), WDB(3 * nq, 2 * n);
  for (int k = 0; k < nq; ++k) {
    B.block(3 * k, 0, 1, n) = e.ev.dN_dx.col(k).transpose();
    B.block(3 * k + 1, n, 1, n) = e.ev.dN_dy.col(k).transpose();
    B.block(3 * k + 2, 0, 1, n) = e.ev.dN_dy.col(k).transpose();
    B.block(3 * k + 2, n, 1, n) = e.ev.dN_dx.col(k).transpose();
    WDB.middleRows(3 * k, 3) = e.ev.JxW(k) * D * B.middleRows(3 * k, 3);
  }
  const Eigen::MatrixXd K_all = B.transpose() * WDB;
  const Eigen::MatrixXd K = fem::stiffness(e.ev, D, 1.0);
  EXPECT_LT((K - K_all).norm(), 1e-12 * K_all.norm());
  const auto at_rest = fem::finite_strain_element(e.ev, {material::Law::neo_hooke, steel()}, 1.0,
                                                  Eigen::VectorXd::Zero(2 * n), true);
  EXPECT_LT((at_rest.K - K_all).norm(), 1e-12 * K_all.norm());
}

// Asked to stop inside stoppable work, the blocks end before the next one starts; elsewhere
// (writing a stopped run's results) every block is taken.
TEST(PointBlocks, AStopEndsThemBetweenBlocks) {
  clear_stop();
  request_stop(SIGTERM);
  int taken = 0;
  fem::for_point_blocks(100, 1e9, [&](int, int) { ++taken; });
  EXPECT_EQ(taken, 13);  // 8 points a block
  taken = 0;
  {
    const StoppableWork armed;
    EXPECT_THROW(fem::for_point_blocks(100, 1e9, [&](int, int) { ++taken; }), Stopped);
  }
  EXPECT_EQ(taken, 0);
  clear_stop();
}
