// The soft-body rope (paper, Section IV-C); its self-contact pass is rope_self_contact.
#include "sim/soft/rope.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/soft/rope_self_contact.hpp"

namespace corrmp {

namespace {

Eigen::Vector3d eigen(const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }
btVector3 bullet(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }

}  // namespace

std::vector<Eigen::Vector3d> straight_rope(const RopeParams& params, const Eigen::Vector3d& start,
                                           const Eigen::Vector3d& direction) {
  if (params.nodes < 2 || direction.norm() == 0) {
    throw std::invalid_argument("straight_rope: needs two nodes and a non-zero direction");
  }
  const Eigen::Vector3d step = direction.normalized() * params.length / (params.nodes - 1);
  std::vector<Eigen::Vector3d> positions;
  for (int i = 0; i < params.nodes; ++i) positions.push_back(start + step * i);
  return positions;
}

Rope::Rope(SoftWorld& world, const RopeParams& params,
           const std::vector<Eigen::Vector3d>& positions)
    : world_(world), params_(params) {
  const int n = static_cast<int>(positions.size());
  if (n != params.nodes || n < 3) {
    throw std::invalid_argument(
        fmt::format("Rope: {} positions for {} nodes (at least 3)", n, params.nodes));
  }
  if (params.colour.size() != 3 || params.end_colour.size() != 3) {
    throw std::invalid_argument("Rope: colour and end_colour need 3 values (RGB)");
  }
  body_ = std::make_unique<btSoftBody>(&world.world_info());
  // Nodes take the first material: stretch links use it.
  btSoftBody::Material* stretch = body_->appendMaterial();
  stretch->m_kLST = params.stretch_stiffness;
  const double node_mass = params.mass / n;
  for (const auto& p : positions) {
    body_->appendNode(world.to_bullet(p), node_mass);
    node_mass_.push_back(node_mass);
  }
  btSoftBody::Material* bend = body_->appendMaterial();
  bend->m_kLST = params.bend_stiffness;
  // Rest lengths come from the rope, not from the start layout (which may be bent).
  const double spacing = world.to_units(params.length / (n - 1));
  for (int i = 0; i + 1 < n; ++i) {
    body_->appendLink(i, i + 1, stretch);
    rest_length_.push_back(spacing);
  }
  for (int i = 0; i + 2 < n; ++i) {
    body_->appendLink(i, i + 2, bend);
    rest_length_.push_back(2 * spacing);
  }
  btSoftBody::Config& cfg = body_->m_cfg;
  cfg.piterations = params.iterations;
  cfg.kDP = params.damping;
  cfg.kDF = params.friction;
  cfg.kCHR = 1.0;
  cfg.kKHR = 1.0;
  cfg.kAHR = params.anchor_hardness;
  cfg.collisions = btSoftBody::fCollision::SDF_RS;
  body_->getCollisionShape()->setMargin(world.to_units(params.radius));
  body_->setActivationState(DISABLE_DEACTIVATION);
  update_constants();
  world.add_soft_body(body_.get());
  world.add_post_step(body_.get(), [this] { self_contact(); });
}

Rope::~Rope() { world_.remove_soft_body(body_.get()); }

int Rope::node_count() const { return body_->m_nodes.size(); }

Eigen::Vector3d Rope::node(int i) const {
  if (i < 0 || i >= node_count()) {
    throw std::out_of_range(fmt::format("Rope::node: index {} of {}", i, node_count()));
  }
  return world_.to_metres(body_->m_nodes[i].m_x);
}

std::vector<Eigen::Vector3d> Rope::nodes() const {
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < node_count(); ++i) out.push_back(world_.to_metres(body_->m_nodes[i].m_x));
  return out;
}

double Rope::length() const {
  double total = 0;
  for (int i = 0; i + 1 < node_count(); ++i) total += (node(i + 1) - node(i)).norm();
  return total;
}

int Rope::first_end_node() const {
  const double spacing = params_.length / (node_count() - 1);
  const int count = static_cast<int>(std::floor(params_.end_length / spacing + 1e-9)) + 1;
  return std::max(0, node_count() - std::max(1, count));
}

Eigen::Vector3d Rope::end_point() const {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const int first = first_end_node();
  for (int i = first; i < node_count(); ++i) sum += node(i);
  return sum / (node_count() - first);
}

void Rope::update_constants() {
  // Bullet recomputes its link constants at the next step after a mass change,
  // taking the rest lengths from the current (possibly bent or stretched) shape;
  // do it now and put the rope's own rest lengths back.
  body_->updateConstants();
  body_->m_bUpdateRtCst = false;
  for (int l = 0; l < body_->m_links.size(); ++l) {
    btSoftBody::Link& link = body_->m_links[l];
    link.m_rl = rest_length_[l];
    link.m_c1 = link.m_rl * link.m_rl;
  }
}

void Rope::pin(int i, bool pinned) {
  node(i);
  body_->setMass(i, pinned ? 0.0 : node_mass_[i]);
  if (pinned) body_->m_nodes[i].m_v.setZero();
  update_constants();
}

void Rope::set_mass(int i, double mass) {
  node(i);
  if (!(mass > 0))
    throw std::invalid_argument(fmt::format("Rope::set_mass: node {} mass {}", i, mass));
  node_mass_[i] = mass;
  if (body_->m_nodes[i].m_im > 0) body_->setMass(i, mass);
  update_constants();
}

void Rope::set_node(int i, const Eigen::Vector3d& position) {
  node(i);
  body_->m_nodes[i].m_x = world_.to_bullet(position);
}

void Rope::self_contact() {
  const int n = node_count();
  RopeContactState& state = contact_;
  state.x.resize(n);
  state.v.resize(n);
  state.inverse_mass.resize(n);
  for (int i = 0; i < n; ++i) {
    state.x[i] = eigen(body_->m_nodes[i].m_x);
    state.v[i] = eigen(body_->m_nodes[i].m_v);
    state.inverse_mass[i] = body_->m_nodes[i].m_im;
  }
  const bool changed = resolve_self_contacts(
      state, {world_.to_units(params_.radius), params_.friction, world_.time_step()});
  if (!changed) return;
  for (int i = 0; i < n; ++i) {
    body_->m_nodes[i].m_x = bullet(state.x[i]);
    body_->m_nodes[i].m_v = bullet(state.v[i]);
  }
}

}  // namespace corrmp
