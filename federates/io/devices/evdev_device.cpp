#include "io/devices/evdev_device.hpp"

#include <libevdev/libevdev.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

namespace fedsim::io {

namespace {

class EvdevDevice final : public EventDevice {
 public:
  EvdevDevice(int fd, libevdev* dev, std::string path) : fd_(fd), dev_(dev), path_(std::move(path)) {}
  ~EvdevDevice() override {
    libevdev_free(dev_);
    ::close(fd_);
  }
  EvdevDevice(const EvdevDevice&) = delete;
  EvdevDevice& operator=(const EvdevDevice&) = delete;

  std::string name() const override {
    const char* n = libevdev_get_name(dev_);
    return n ? n : "";
  }
  std::string path() const override { return path_; }
  int fd() const override { return fd_; }

  bool poll(std::vector<DeviceReading>& readings) override {
    unsigned flags = LIBEVDEV_READ_FLAG_NORMAL;
    for (;;) {
      input_event ev{};
      const int rc = libevdev_next_event(dev_, flags, &ev);
      if (rc == -EAGAIN) {
        if (flags == LIBEVDEV_READ_FLAG_SYNC) {  // resynchronised: back to normal reading
          flags = LIBEVDEV_READ_FLAG_NORMAL;
          continue;
        }
        return true;
      }
      if (rc == LIBEVDEV_READ_STATUS_SYNC) {
        // The kernel's buffer overflowed (SYN_DROPPED): libevdev replays the changed state.
        flags = LIBEVDEV_READ_FLAG_SYNC;
        add(ev, readings);
        continue;
      }
      if (rc != LIBEVDEV_READ_STATUS_SUCCESS) return false;  // -ENODEV: unplugged
      add(ev, readings);
    }
  }

  std::vector<AxisInfo> axes() const override {
    std::vector<AxisInfo> out;
    for (unsigned code = 0; code <= ABS_MAX; ++code) {
      if (!libevdev_has_event_code(dev_, EV_ABS, code)) continue;
      const input_absinfo* info = libevdev_get_abs_info(dev_, code);
      if (info == nullptr) continue;
      out.push_back({code_name(EV_ABS, code), static_cast<double>(info->minimum),
                     static_cast<double>(info->maximum), static_cast<double>(info->value)});
    }
    return out;
  }

  std::vector<DeviceReading> contacts() const override {
    std::vector<DeviceReading> out;
    for (unsigned code = 0; code <= KEY_MAX; ++code) {
      if (!libevdev_has_event_code(dev_, EV_KEY, code)) continue;
      out.push_back({DeviceReading::Kind::kContact, code_name(EV_KEY, code),
                     libevdev_get_event_value(dev_, EV_KEY, code) != 0 ? 1.0 : 0.0});
    }
    return out;
  }

 private:
  static std::string code_name(unsigned type, unsigned code) {
    const char* n = libevdev_event_code_get_name(type, code);
    return n ? n : std::to_string(type) + ":" + std::to_string(code);
  }
  static void add(const input_event& ev, std::vector<DeviceReading>& readings) {
    if (ev.type == EV_ABS) {
      readings.push_back({DeviceReading::Kind::kAxis, code_name(EV_ABS, ev.code), static_cast<double>(ev.value)});
    } else if (ev.type == EV_KEY) {
      // value 2 is the kernel's autorepeat of a held key: still pressed.
      readings.push_back({DeviceReading::Kind::kContact, code_name(EV_KEY, ev.code), ev.value != 0 ? 1.0 : 0.0});
    }
  }

  int fd_;
  libevdev* dev_;
  std::string path_;
};

std::unique_ptr<EventDevice> try_open(const std::string& path, std::string* error) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    if (error) *error = std::strerror(errno);
    return nullptr;
  }
  libevdev* dev = nullptr;
  const int rc = libevdev_new_from_fd(fd, &dev);
  if (rc < 0) {
    if (error) *error = std::string("not an evdev device: ") + std::strerror(-rc);
    ::close(fd);
    return nullptr;
  }
  return std::make_unique<EvdevDevice>(fd, dev, path);
}

std::vector<std::string> event_paths() {
  std::vector<std::string> out;
  DIR* dir = ::opendir("/dev/input");
  if (dir == nullptr) return out;
  while (const dirent* e = ::readdir(dir)) {
    if (std::strncmp(e->d_name, "event", 5) == 0) out.push_back(std::string("/dev/input/") + e->d_name);
  }
  ::closedir(dir);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

std::unique_ptr<EventDevice> open_evdev(const std::string& path) {
  std::string error;
  auto device = try_open(path, &error);
  if (!device) throw DeviceError("input device " + path + ": " + error);
  return device;
}

std::unique_ptr<EventDevice> find_evdev(const std::string& name) {
  for (const std::string& path : event_paths()) {
    auto device = try_open(path, nullptr);
    if (device && device->name() == name) return device;
  }
  return nullptr;
}

std::vector<EvdevListing> list_evdev() {
  std::vector<EvdevListing> out;
  for (const std::string& path : event_paths()) {
    auto device = try_open(path, nullptr);
    if (!device) continue;
    out.push_back({path, device->name(), static_cast<int>(device->axes().size()),
                   static_cast<int>(device->contacts().size())});
  }
  return out;
}

DeviceOpener evdev_opener(const std::string& path, const std::string& name) {
  return [path, name]() -> std::unique_ptr<EventDevice> {
    if (!path.empty()) return try_open(path, nullptr);
    return find_evdev(name);
  };
}

}  // namespace fedsim::io
