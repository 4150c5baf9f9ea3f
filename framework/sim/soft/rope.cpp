// The soft-body rope and its self-contact pass (paper, Section IV-C).
#include "sim/soft/rope.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace corrmp {

namespace {

Eigen::Vector3d eigen(const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }
btVector3 bullet(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }

// Closest points of segments [p0, p1] and [q0, q1]: parameters s and t in [0, 1].
// A zero-length segment is a point (its parameter is 0).
void closest_parameters(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                        const Eigen::Vector3d& q0, const Eigen::Vector3d& q1, double& s,
                        double& t) {
  const Eigen::Vector3d d1 = p1 - p0;
  const Eigen::Vector3d d2 = q1 - q0;
  const Eigen::Vector3d r = p0 - q0;
  const double a = d1.squaredNorm();
  const double e = d2.squaredNorm();
  const double f = d2.dot(r);
  const double c = d1.dot(r);
  const double b = d1.dot(d2);
  constexpr double kTiny = 1e-24;  // squared length of a zero-length segment
  if (a <= kTiny && e <= kTiny) {
    s = t = 0.0;
    return;
  }
  if (a <= kTiny) {
    s = 0.0;
    t = std::clamp(f / e, 0.0, 1.0);
    return;
  }
  if (e <= kTiny) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
    return;
  }
  const double denom = a * e - b * b;
  s = denom > 1e-12 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
}

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
  std::vector<Eigen::Vector3d> x(n), v(n);
  std::vector<double> im(n);
  for (int i = 0; i < n; ++i) {
    x[i] = eigen(body_->m_nodes[i].m_x);
    v[i] = eigen(body_->m_nodes[i].m_v);
    im[i] = body_->m_nodes[i].m_im;
  }
  const double contact = 2.0 * world_.to_units(params_.radius);
  double longest = 0;
  for (int i = 0; i + 1 < n; ++i) longest = std::max(longest, (x[i + 1] - x[i]).norm());
  const double reach = longest + contact;
  bool changed = false;
  double moved = 0;  // bounds how far any node has been pushed in this pass

  // Segments i and j (j >= i + 3) in contact are resolved at once, in the
  // order of (i, j); returns whether they were.
  auto resolve = [&](int i, int j) {
    if ((x[i] + x[i + 1] - x[j] - x[j + 1]).squaredNorm() > 4.0 * reach * reach) return false;
    double s = 0, t = 0;
    closest_parameters(x[i], x[i + 1], x[j], x[j + 1], s, t);
    const Eigen::Vector3d p = x[i] + s * (x[i + 1] - x[i]);
    const Eigen::Vector3d q = x[j] + t * (x[j + 1] - x[j]);
    Eigen::Vector3d normal = p - q;
    const double distance = normal.norm();
    if (distance >= contact || distance < 1e-9) return false;
    normal /= distance;
    const int k[4] = {i, i + 1, j, j + 1};
    const double w[4] = {1 - s, s, -(1 - t), -t};
    double weight = 0;
    for (int m = 0; m < 4; ++m) weight += w[m] * w[m] * im[k[m]];
    if (weight <= 0) return false;
    const double push = (contact - distance) / weight;
    Eigen::Vector3d relative = Eigen::Vector3d::Zero();
    for (int m = 0; m < 4; ++m) relative += w[m] * v[k[m]];
    const double approach = relative.dot(normal);
    const double normal_impulse = approach < 0 ? -approach / weight : 0.0;
    const Eigen::Vector3d tangential = relative - approach * normal;
    const double slide = tangential.norm();
    Eigen::Vector3d friction = Eigen::Vector3d::Zero();
    if (slide > 1e-12) {
      const double stop = slide / weight;
      const double limit = params_.friction * (normal_impulse + push / world_.time_step());
      friction = -std::min(stop, limit) * tangential / slide;
    }
    double largest = 0;
    for (int m = 0; m < 4; ++m) {
      const double scale = w[m] * im[k[m]];
      x[k[m]] += scale * push * normal;
      v[k[m]] += scale * (normal_impulse * normal + friction);
      largest = std::max(largest, std::abs(scale * push));
    }
    moved += largest;
    return changed = true;
  };

  // Every pair from (i0, j0) on, in order: the plain sweep.
  auto resolve_all_from = [&](int i0, int j0) {
    for (int i = i0; i + 1 < n; ++i)
      for (int j = i == i0 ? j0 : i + 3; j + 1 < n; ++j) resolve(i, j);
  };

  // The same pairs in the same order, found faster: a pair whose segment
  // midpoint sums (x_i + x_i+1) lie further apart than 2 reach + slack at the
  // start cannot pass resolve()'s first test while the nodes have moved less
  // than slack / 4 in all; past half of that, the plain sweep takes over.
  const double slack = contact;
  const double window = 2.0 * reach + slack;
  const int segments = n - 1;
  std::vector<Eigen::Vector3d> sum(std::max(segments, 0));
  for (int i = 0; i < segments; ++i) sum[i] = x[i] + x[i + 1];
  int axis = 0;  // swept along the axis the rope spans most
  if (segments > 0) {
    Eigen::Vector3d lo = sum[0], hi = sum[0];
    for (const Eigen::Vector3d& s : sum) lo = lo.cwiseMin(s), hi = hi.cwiseMax(s);
    (hi - lo).maxCoeff(&axis);
  }
  std::vector<int> order(sum.size());
  for (int i = 0; i < segments; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return sum[a][axis] < sum[b][axis]; });
  std::vector<std::pair<int, int>> candidates;
  for (int a = 0; a < segments; ++a) {
    for (int b = a + 1; b < segments && sum[order[b]][axis] - sum[order[a]][axis] <= window; ++b) {
      const int i = std::min(order[a], order[b]), j = std::max(order[a], order[b]);
      if (j >= i + 3 && (sum[i] - sum[j]).squaredNorm() <= window * window)
        candidates.emplace_back(i, j);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  for (const auto& [i, j] : candidates) {
    if (resolve(i, j) && 4.0 * moved > 0.5 * slack) {
      resolve_all_from(i, j + 1);
      break;
    }
  }

  if (!changed) return;
  for (int i = 0; i < n; ++i) {
    body_->m_nodes[i].m_x = bullet(x[i]);
    body_->m_nodes[i].m_v = bullet(v[i]);
  }
}

}  // namespace corrmp
