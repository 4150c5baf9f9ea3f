// The serial chain of a RobotModel from one link down to another as a KDL
// chain, for KDL's kinematics solvers: one segment per joint (fixed joints as
// Joint::Fixed segments), each ending in its child link's frame and carrying
// that link's inertia.
#pragma once

#include <kdl/chain.hpp>
#include <string>

#include "sim/robot/robot_model.hpp"

namespace corrmp {

// Throws ConfigError (RobotModel::chain) when `tip` is not below `base`.
KDL::Chain kdl_chain(const RobotModel& model, const std::string& base, const std::string& tip);

}  // namespace corrmp
