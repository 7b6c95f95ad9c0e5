#include "fedsim/io_cli.hpp"

#include "io/devices/evdev_device.hpp"
#include "io/model/inceptor_mapper.hpp"

#include <poll.h>
#include <unistd.h>

#include <fstream>
#include <iostream>
#include <stdexcept>

namespace fedsim::launcher {

namespace {

constexpr int kExitWritten = 0;
constexpr int kExitFailed = 1;
constexpr int kExitBadArgument = 2;

struct Mapping {
  std::string source;
  io::Channel channel;
  std::string flag;  // "reversed" / "toggle" / ""
};

Mapping parse_mapping(const std::string& text, const std::string& allowed_flag) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw std::invalid_argument("'" + text + "': expected SOURCE=CHANNEL[:" + allowed_flag + "]");
  }
  Mapping m;
  m.source = text.substr(0, eq);
  std::string channel = text.substr(eq + 1);
  if (const auto colon = channel.find(':'); colon != std::string::npos) {
    m.flag = channel.substr(colon + 1);
    channel = channel.substr(0, colon);
    if (m.flag != allowed_flag) throw std::invalid_argument("'" + text + "': the only flag is :" + allowed_flag);
  }
  m.channel = io::channel_called(channel);
  return m;
}

/// Waits for the user's Enter while draining the device into the recorder; false when stdin
/// closed first.
bool record_until_enter(io::EventDevice& device, const std::string& source, io::CalibrationRecorder& recorder,
                        double& present, std::istream& in, std::ostream& out) {
  std::vector<io::DeviceReading> readings;
  for (;;) {
    pollfd fds[2] = {{device.fd(), POLLIN, 0}, {STDIN_FILENO, POLLIN, 0}};
    const bool real_stdin = &in == &std::cin;
    ::poll(fds, real_stdin ? 2 : 1, 100);
    readings.clear();
    if (!device.poll(readings)) throw std::runtime_error("the device went away during the calibration");
    for (const auto& r : readings) {
      if (r.kind == io::DeviceReading::Kind::kAxis && r.source == source) {
        present = r.value;
        recorder.observe(r.value);
      }
    }
    if (!real_stdin || (fds[1].revents & (POLLIN | POLLHUP)) != 0) {
      std::string line;
      if (!std::getline(in, line)) return false;
      out << "  " << source << ": seen " << recorder.seen_min() << " .. " << recorder.seen_max() << ", at rest "
          << present << "\n";
      return true;
    }
  }
}

std::unique_ptr<io::EventDevice> open_device(const CalibrateOptions& o) {
  if (!o.device.empty() && !o.device_name.empty()) throw std::invalid_argument("give --device or --device-name, not both");
  if (!o.device.empty()) return io::open_evdev(o.device);
  if (o.device_name.empty()) throw std::invalid_argument("--device PATH or --device-name NAME is needed");
  auto d = io::find_evdev(o.device_name);
  if (!d) throw io::DeviceError("no readable input device is named '" + o.device_name + "' (fedsim io calibrate --list)");
  return d;
}

int list_devices(std::ostream& out) {
  const auto devices = io::list_evdev();
  if (devices.empty()) {
    out << "no readable input devices in /dev/input (none plugged in, or no permission: the input group)\n";
    return kExitFailed;
  }
  for (const auto& d : devices) out << d.path << "  '" << d.name << "'  " << d.axes << " axes, " << d.buttons << " buttons\n";
  return kExitWritten;
}

}  // namespace

namespace {
/// The mappings the options ask for; throws std::invalid_argument.
void parse_options(const CalibrateOptions& o, std::vector<Mapping>& axes, std::vector<Mapping>& buttons) {
  if (o.out.empty()) throw std::invalid_argument("--out FILE is needed");
  if (o.axes.empty() && o.buttons.empty()) throw std::invalid_argument("give at least one --axis or --button");
  if (!(o.dead_zone >= 0.0 && o.dead_zone < 0.5)) throw std::invalid_argument("--dead-zone must lie in [0, 0.5)");
  for (const auto& a : o.axes) axes.push_back(parse_mapping(a, "reversed"));
  for (const auto& b : o.buttons) buttons.push_back(parse_mapping(b, "toggle"));
}
}  // namespace

int io_calibrate(const CalibrateOptions& o, std::istream& in, std::ostream& out, std::ostream& err) {
  if (o.list) return list_devices(out);
  std::unique_ptr<io::EventDevice> device;
  try {
    std::vector<Mapping> axes, buttons;
    parse_options(o, axes, buttons);  // before the device: a typo is named without one
    device = open_device(o);
  } catch (const std::exception& e) {
    err << "fedsim io calibrate: " << e.what() << "\n";
    return kExitBadArgument;
  }
  return io_calibrate_device(*device, o, in, out, err);
}

int io_calibrate_device(io::EventDevice& device_ref, const CalibrateOptions& o, std::istream& in,
                        std::ostream& out, std::ostream& err) {
  io::EventDevice* device = &device_ref;
  std::vector<Mapping> axes, buttons;
  try {
    parse_options(o, axes, buttons);
  } catch (const std::exception& e) {
    err << "fedsim io calibrate: " << e.what() << "\n";
    return kExitBadArgument;
  }
  const auto device_axes = device->axes();
  io::InceptorCalibration calibration;
  calibration.device_name = device->name();
  out << "calibrating '" << device->name() << "' at " << device->path() << "\n";
  try {
    for (const Mapping& m : axes) {
      const io::AxisInfo* info = nullptr;
      for (const auto& a : device_axes) info = a.source == m.source ? &a : info;
      if (info == nullptr) {
        std::string known;
        for (const auto& a : device_axes) known += " " + a.source;
        throw std::invalid_argument("the device has no axis " + m.source + " (it has:" + known + ")");
      }
      out << "axis " << m.source << " -> " << io::channel_info(m.channel).name
          << ": move it to both stops, let it come to rest, then press Enter\n";
      io::CalibrationRecorder recorder;
      recorder.start(m.source, m.channel, info->minimum, info->maximum);
      double present = info->value;
      recorder.observe(present);
      if (!record_until_enter(*device, m.source, recorder, present, in, out)) {
        err << "fedsim io calibrate: stdin closed before the calibration ended: nothing written\n";
        return kExitFailed;
      }
      io::AxisCalibration a = recorder.finish(present);
      a.reversed = m.flag == "reversed";
      a.dead_zone = io::bipolar(m.channel) ? o.dead_zone : 0.0;
      calibration.axes.push_back(a);
    }
    const auto contacts = device->contacts();
    for (const Mapping& m : buttons) {
      bool found = false;
      for (const auto& c : contacts) found = found || c.source == m.source;
      if (!found) throw std::invalid_argument("the device has no button " + m.source);
      io::DiscreteCalibration d;
      d.source = m.source;
      d.channel = m.channel;
      d.mode = m.flag == "toggle" ? io::DiscreteMode::kToggle : io::DiscreteMode::kMomentary;
      calibration.discretes.push_back(d);
    }
  } catch (const std::invalid_argument& e) {
    err << "fedsim io calibrate: " << e.what() << "\n";
    return kExitBadArgument;
  } catch (const std::exception& e) {
    err << "fedsim io calibrate: " << e.what() << ": nothing written\n";
    return kExitFailed;
  }
  const std::string yaml = calibration.to_yaml();
  io::InceptorCalibration::parse(yaml, o.out);  // what it writes, it reads back
  std::ofstream file(o.out);
  file << yaml;
  if (!file) {
    err << "fedsim io calibrate: cannot write " << o.out << "\n";
    return kExitBadArgument;
  }
  out << "wrote " << o.out << " (" << calibration.axes.size() << " axes, " << calibration.discretes.size()
      << " discretes)\n";
  return kExitWritten;
}

void add_io_commands(CLI::App& app, int& exit_code) {
  auto* io_cmd = app.add_subcommand("io", "pilot inceptors: calibrate a joystick, yoke, pedals or throttle");
  io_cmd->require_subcommand(1);
  auto o = std::make_shared<CalibrateOptions>();
  auto* cal = io_cmd->add_subcommand("calibrate", "write a calibration file, moving each axis to its stops");
  cal->add_flag("--list", o->list, "list the readable input devices and exit");
  cal->add_option("--device", o->device, "the device, e.g. /dev/input/event5");
  cal->add_option("--device-name", o->device_name, "the device by name");
  cal->add_option("--axis", o->axes, "SOURCE=CHANNEL[:reversed], e.g. ABS_Y=elevator:reversed");
  cal->add_option("--button", o->buttons, "SOURCE=CHANNEL[:toggle], e.g. BTN_TRIGGER=ap_disconnect");
  cal->add_option("--dead-zone", o->dead_zone, "dead zone of centred axes (fraction of half travel)")
      ->capture_default_str();
  cal->add_option("--out", o->out, "the calibration file to write");
  cal->callback([o, &exit_code] { exit_code = io_calibrate(*o, std::cin, std::cout, std::cerr); });
}

}  // namespace fedsim::launcher
