// The simulated rope of the knotting task (paper, Section IV-C): a Bullet soft
// body built node by node, stretch links between neighbours and bending links
// between nodes i and i+2, and a segment-segment self-contact pass after each
// step (Bullet's soft-body self-collision does not work for ropes; without the
// pass no knot can form). Positions are in metres.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "core/config/field_rule.hpp"
#include "sim/soft/rope_self_contact.hpp"
#include "sim/soft/soft_world.hpp"

namespace corrmp {

struct RopeParams {
  double length = 0.95;
  int nodes = 96;
  double radius = 0.005;
  double mass = 0.04;
  double stretch_stiffness = 1.0;
  double bend_stiffness = 0.05;
  double damping = 0.02;
  double friction = 0.6;
  double anchor_hardness = 0.7;
  int iterations = 10;
  std::vector<double> colour{0.85, 0.8, 0.65};
  std::vector<double> end_colour{0.9, 0.1, 0.1};
  double end_length = 0.05;

  template <class Fields>
  void describe(Fields& f) {
    f("length", length, "rope length (m)", positive());
    f("nodes", nodes, "soft-body nodes along the rope", in_range(3, 10000));
    f("radius", radius, "rope radius (m); contacts keep two radii between segments", positive());
    f("mass", mass, "total mass (kg)", positive());
    f("stretch_stiffness", stretch_stiffness, "linear stiffness of neighbour links",
      in_range(0.0, 1.0));
    f("bend_stiffness", bend_stiffness, "linear stiffness of the i, i+2 bending links",
      in_range(0.0, 1.0));
    f("damping", damping, "velocity damping coefficient", in_range(0.0, 1.0));
    f("friction", friction, "friction with rigid bodies and with itself", in_range(0.0, 1.0));
    f("anchor_hardness", anchor_hardness, "anchor stiffness; below 1 (at 1 it cancels itself)",
      in_range(0.0, 0.99));
    f("iterations", iterations, "position solver iterations per step", in_range(1, 200));
    f("colour", colour, "RGB in [0, 1]", size_is(3).at_least(0.0).at_most(1.0));
    f("end_colour", end_colour, "RGB of the coloured free end, in [0, 1]",
      size_is(3).at_least(0.0).at_most(1.0));
    f("end_length", end_length, "length of the coloured free end (m)", at_least(0.0));
  }
};

class Rope {
 public:
  // Builds the rope through `positions` (one per node, metres, about
  // length / (nodes - 1) apart) and adds it to `world`. Rest lengths are those
  // of a straight rope: length / (nodes - 1) between neighbours, twice that
  // for the bending links.
  Rope(SoftWorld& world, const RopeParams& params, const std::vector<Eigen::Vector3d>& positions);
  ~Rope();
  Rope(const Rope&) = delete;
  Rope& operator=(const Rope&) = delete;

  int node_count() const;
  Eigen::Vector3d node(int i) const;
  std::vector<Eigen::Vector3d> nodes() const;
  double length() const;  // current length along the nodes
  // Node indices of the coloured free end (the last end_length of the rope).
  int first_end_node() const;
  Eigen::Vector3d end_point() const;  // centroid of the coloured end's nodes
  const RopeParams& params() const { return params_; }

  // Pins node i where it is (infinite mass) or gives it back its mass.
  void pin(int i, bool pinned);
  // Sets node i's mass (kg), e.g. to hang a weight on the rope.
  void set_mass(int i, double mass);
  // Overwrites node i's position (tests, fault injection).
  void set_node(int i, const Eigen::Vector3d& position);

  // The self-contact pass: pushes non-adjacent segments closer than two radii
  // apart (by inverse mass), removes their approaching velocity, applies friction.
  void self_contact();

  btSoftBody& body() { return *body_; }
  SoftWorld& world() { return world_; }

 private:
  void update_constants();

  SoftWorld& world_;
  RopeParams params_;
  std::unique_ptr<btSoftBody> body_;  // removed from the world before it is destroyed
  std::vector<double> node_mass_;
  std::vector<double> rest_length_;  // per link, Bullet units
  RopeContactState contact_;         // the self-contact pass's nodes and scratch
};

// Node positions of a straight rope from `start` along `direction`.
std::vector<Eigen::Vector3d> straight_rope(const RopeParams& params, const Eigen::Vector3d& start,
                                           const Eigen::Vector3d& direction);

}  // namespace corrmp
