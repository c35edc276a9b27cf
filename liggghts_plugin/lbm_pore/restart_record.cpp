#include "restart_record.h"

#include <cstring>

namespace lbm_pore {

namespace {
void append_values(std::string& out, const std::vector<double>& values) {
  const double count = double(values.size());
  out.append(reinterpret_cast<const char*>(&count), sizeof(double));
  out.append(reinterpret_cast<const char*>(values.data()), sizeof(double) * values.size());
}

// Reads a count and as many values at `at`; returns the position after them.
const char* read_values(const char* at, std::vector<double>& values) {
  double count = 0.0;
  std::memcpy(&count, at, sizeof(double));
  values.resize(static_cast<std::size_t>(count));
  std::memcpy(values.data(), at + sizeof(double), sizeof(double) * values.size());
  return at + sizeof(double) * (values.size() + 1);
}
}  // namespace

std::string RestartRecord::bytes() const {
  std::string out(reinterpret_cast<const char*>(&kTagWithDrive), sizeof(double));
  append_values(out, monitor_state);
  append_values(out, drive_state);
  out.append(checkpoint.c_str(), checkpoint.size() + 1);
  return out;
}

RestartRecord RestartRecord::read(const char* bytes) {
  RestartRecord record;
  double first = 0.0;
  std::memcpy(&first, bytes, sizeof(double));
  const bool with_drive = first == kTagWithDrive;
  const char* at = read_values(with_drive ? bytes + sizeof(double) : bytes, record.monitor_state);
  if (with_drive) at = read_values(at, record.drive_state);
  record.checkpoint = std::string(at);
  return record;
}

std::string checkpoint_prefix(const PoreOptions& options, const std::string& fix_id) {
  return options.checkpoint_prefix.empty() ? fix_id + ".fluid" : options.checkpoint_prefix;
}

std::string checkpoint_path(const std::string& prefix, long long step) {
  return prefix + "." + std::to_string(step);
}

}  // namespace lbm_pore
