// What a task on the dual-arm torso measures of its robot. Per trial, in the
// trial's details: the robot's largest joint tracking error (rad; m for a
// prismatic joint) and its IK solves and failures. Per run, from those details
// only (so the same trials give the same metrics): the IK's success rate and the
// tracking error. The IK's wall time per solve is not deterministic: it goes in
// the run's printed tables, never in its metrics.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/metric.hpp"
#include "data/evaluated_trial.hpp"
#include "sim/robot/dual_arm.hpp"
#include "sim/robot/ik_solve_times.hpp"

namespace corrmp {

// Adds max_tracking_error, ik_solves and ik_failures of `robot` (since its reset) to a trial's
// details.
void add_robot_details(const DualArm& robot, std::map<std::string, double>& details);

// Over the trials whose details add_robot_details filled (the others are skipped): ik_solves
// (their sum), ik_success_rate (1 - failures / solves; left out without solves) and
// joint_tracking_error_mean_rad and joint_tracking_error_max_rad (the mean and the largest of
// the trials' largest joint tracking errors, one report column). None when no trial has them.
std::vector<Metric> robot_run_metrics(const std::vector<EvaluatedTrial>& trials);

// The run's log line of the IK's wall time: "IK time (<label>): N solves, median X us,
// mean Y us per solve"; "" without solves.
std::string ik_time_log_line(const IkSolveTimes& times, const std::string& label);

}  // namespace corrmp
