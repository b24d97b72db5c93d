// A hybrid force/velocity controller shaped like a ros2_control controller, around the standalone C that
// `python -m hybrid generate` writes (NAME_controller.c/.h). No ROS dependency: plain std types stand
// for rclcpp's and hardware_interface's, with the same names and lifecycle, so that porting it into a
// controller_interface::ControllerInterface is a matter of swapping the types.
//
//   extern "C" {
//   #include "ur5_controller.h"
//   }
//   #include "hybrid_controller.hpp"
//   HYBRID_CONTROLLER_TRAITS(ur5)                          // ur5_traits: the generated C's entry points
//   hybrid_ros2_like::HybridController<ur5_traits> ctrl;
//   ctrl.on_init();                                        // the generated configuration
//   ctrl.on_configure({joints, "tcp_fts"});                // which interfaces it claims
//   ctrl.assign_interfaces(commands, states);              // the controller manager's loan, in the order of
//                                                          // command/state_interface_configuration()
//   ctrl.on_activate();
//   every period: ret = ctrl.update(time, period);         // reads q, qd, the wrench; writes the efforts
//
// State interfaces, in order: <joint>/position and <joint>/velocity for each joint, then the wrench
// <sensor>/force.x .. force.z, <sensor>/torque.x .. torque.z: the force and moment ON THE ROBOT at the
// tip frame's origin, in base axes [N, N m] (the generated step's convention; transform a sensor's own
// reading upstream). Command interfaces: <joint>/effort for each joint [N m or N].
//
// update(): the sample's time is `time` less the first update's after activation (the experiment's
// clock: the references' steps are at their times from there). Every status of the step other than
// <NAME>_OK makes update() return return_type::ERROR and hold the effort commands at their last values
// (0 before any): the law failing (SINGULAR, NONFINITE, FRAME_UNDEFINED, EULER_SINGULAR), a non-finite
// measurement (INPUT_NONFINITE; the step's clock then did not move, so the next sample on time is late by
// one period and held too), a sample off the step's clock (SAMPLE_LATE, SAMPLE_EARLY, SAMPLE_REPEATED,
// SAMPLE_BACKWARDS; the loops' integrals did not advance, and the step's record of the last torque is
// set back to the held one, so a torque rate limit starts from what the arm got). last_status() and
// last_status_name() tell which.
#ifndef HYBRID_ROS2_LIKE_HYBRID_CONTROLLER_HPP
#define HYBRID_ROS2_LIKE_HYBRID_CONTROLLER_HPP

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

// The traits of the generated controller of prefix NAME (its header included first, in extern "C"):
// the struct, its entry points and its joint count, as NAME_traits.
#define HYBRID_CONTROLLER_TRAITS(NAME)                                                                   \
    struct NAME##_traits {                                                                               \
        using c_type = NAME##_controller;                                                                \
        static constexpr std::size_t nq = sizeof(static_cast<c_type *>(nullptr)->tau) / sizeof(double); \
        static void init(c_type *c) { NAME##_controller_init(c); }                                      \
        static void reset(c_type *c) { NAME##_controller_reset(c); }                                    \
        static int step(c_type *c, double t, const double *q, const double *qd, const double *wrench,    \
                        double *tau) {                                                                   \
            return NAME##_controller_step(c, t, q, qd, wrench, tau);                                     \
        }                                                                                                \
        static const char *status_name(int status) { return NAME##_status_name(status); }               \
    };

namespace hybrid_ros2_like {

// controller_interface::return_type
enum class return_type { OK, ERROR };
// rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn
enum class CallbackReturn { SUCCESS, FAILURE, ERROR };

// rclcpp::Time and rclcpp::Duration, in seconds
class Time {
public:
    explicit Time(double seconds = 0.0) : seconds_(seconds) {}
    double seconds() const { return seconds_; }

private:
    double seconds_;
};

class Duration {
public:
    explicit Duration(double seconds = 0.0) : seconds_(seconds) {}
    double seconds() const { return seconds_; }

private:
    double seconds_;
};

// hardware_interface::LoanedStateInterface / LoanedCommandInterface: a name and the hardware's number
class LoanedStateInterface {
public:
    LoanedStateInterface(std::string name, const double *value) : name_(std::move(name)), value_(value) {}
    const std::string &get_name() const { return name_; }
    double get_value() const { return *value_; }

private:
    std::string name_;
    const double *value_;
};

class LoanedCommandInterface {
public:
    LoanedCommandInterface(std::string name, double *value) : name_(std::move(name)), value_(value) {}
    const std::string &get_name() const { return name_; }
    double get_value() const { return *value_; }
    void set_value(double value) { *value_ = value; }

private:
    std::string name_;
    double *value_;
};

// controller_interface::InterfaceConfiguration (INDIVIDUAL: the names, in order)
struct InterfaceConfiguration {
    std::vector<std::string> names;
};

// what a ros2_control controller reads from its node's parameters
struct Parameters {
    std::vector<std::string> joints;  // one per joint of the generated controller, in its order
    std::string sensor;               // the prefix of the wrench's state interfaces
};

template <class Traits>
class HybridController {
public:
    using c_type = typename Traits::c_type;
    static constexpr std::size_t nq = Traits::nq;

    // the generated configuration (gains, references, model, surface, limits) and a zero state
    CallbackReturn on_init() {
        Traits::init(&c_);
        initialised_ = true;
        return CallbackReturn::SUCCESS;
    }

    CallbackReturn on_configure(const Parameters &parameters) {
        if (!initialised_ || parameters.joints.size() != nq || parameters.sensor.empty()) {
            return CallbackReturn::FAILURE;
        }
        parameters_ = parameters;
        configured_ = true;
        return CallbackReturn::SUCCESS;
    }

    InterfaceConfiguration command_interface_configuration() const {
        InterfaceConfiguration out;
        for (const auto &joint : parameters_.joints) out.names.push_back(joint + "/effort");
        return out;
    }

    InterfaceConfiguration state_interface_configuration() const {
        InterfaceConfiguration out;
        for (const auto &joint : parameters_.joints) out.names.push_back(joint + "/position");
        for (const auto &joint : parameters_.joints) out.names.push_back(joint + "/velocity");
        for (const char *axis : {"force.x", "force.y", "force.z", "torque.x", "torque.y", "torque.z"}) {
            out.names.push_back(parameters_.sensor + "/" + axis);
        }
        return out;
    }

    // the controller manager's loan: the interfaces of the two configurations, by name (any order)
    void assign_interfaces(std::vector<LoanedCommandInterface> commands, std::vector<LoanedStateInterface> states) {
        commands_ = std::move(commands);
        states_ = std::move(states);
    }

    void release_interfaces() {
        commands_.clear();
        states_.clear();
    }

    // claims the configured interfaces (FAILURE when one is missing), starts a new run: the loops'
    // integrals and the sample clock at zero; the efforts it holds on an error before its first good
    // sample are 0 (the generated step's convention); the commands are not touched until the first update
    CallbackReturn on_activate() {
        if (!configured_ || !order(command_interface_configuration(), commands_) ||
            !order(state_interface_configuration(), states_)) {
            return CallbackReturn::FAILURE;
        }
        Traits::reset(&c_);
        held_.fill(0.0);
        has_t0_ = false;
        status_ = 0;
        active_ = true;
        return CallbackReturn::SUCCESS;
    }

    CallbackReturn on_deactivate() {
        active_ = false;
        return CallbackReturn::SUCCESS;
    }

    // one control sample: q, qd and the wrench from the state interfaces, the efforts to the commands
    return_type update(const Time &time, const Duration & /* period: the step keeps its own clock */) {
        if (!active_) return return_type::ERROR;
        if (!has_t0_) {
            t0_ = time.seconds();
            has_t0_ = true;
        }
        std::array<double, nq> q{}, qd{}, tau{};
        std::array<double, 6> wrench{};
        for (std::size_t i = 0; i < nq; ++i) {
            q[i] = states_[i].get_value();
            qd[i] = states_[nq + i].get_value();
        }
        for (std::size_t i = 0; i < 6; ++i) wrench[i] = states_[2 * nq + i].get_value();
        status_ = Traits::step(&c_, time.seconds() - t0_, q.data(), qd.data(), wrench.data(), tau.data());
        if (status_ != 0) {
            // hold: the arm keeps the last efforts, and the step's rate limit starts from them
            for (std::size_t i = 0; i < nq; ++i) c_.tau[i] = held_[i];
            for (std::size_t i = 0; i < nq; ++i) commands_[i].set_value(held_[i]);
            return return_type::ERROR;
        }
        held_ = tau;
        for (std::size_t i = 0; i < nq; ++i) commands_[i].set_value(tau[i]);
        return return_type::OK;
    }

    int last_status() const { return status_; }
    const char *last_status_name() const { return Traits::status_name(status_); }
    // the generated struct: its configuration fields may change between samples (gains, references)
    c_type &controller() { return c_; }
    const c_type &controller() const { return c_; }

private:
    // `loaned` sorted into the order of `wanted`; false when one is missing
    template <class Loaned>
    static bool order(const InterfaceConfiguration &wanted, std::vector<Loaned> &loaned) {
        std::vector<Loaned> sorted;
        for (const auto &name : wanted.names) {
            bool found = false;
            for (const auto &l : loaned) {
                if (l.get_name() == name) {
                    sorted.push_back(l);
                    found = true;
                    break;
                }
            }
            if (!found) return false;
        }
        loaned = std::move(sorted);
        return true;
    }

    c_type c_{};
    Parameters parameters_;
    std::vector<LoanedCommandInterface> commands_;
    std::vector<LoanedStateInterface> states_;
    std::array<double, nq> held_{};
    double t0_ = 0.0;
    bool has_t0_ = false, initialised_ = false, configured_ = false, active_ = false;
    int status_ = 0;
};

}  // namespace hybrid_ros2_like

#endif
