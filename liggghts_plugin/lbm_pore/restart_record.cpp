#include "restart_record.h"

#include <cstring>

namespace lbm_pore {

std::string RestartRecord::bytes() const {
  const double count = double(monitor_state.size());
  std::string out(reinterpret_cast<const char*>(&count), sizeof(double));
  out.append(reinterpret_cast<const char*>(monitor_state.data()), sizeof(double) * monitor_state.size());
  out.append(checkpoint.c_str(), checkpoint.size() + 1);
  return out;
}

RestartRecord RestartRecord::read(const char* bytes) {
  RestartRecord record;
  double count = 0.0;
  std::memcpy(&count, bytes, sizeof(double));
  record.monitor_state.resize(static_cast<std::size_t>(count));
  std::memcpy(record.monitor_state.data(), bytes + sizeof(double), sizeof(double) * record.monitor_state.size());
  record.checkpoint = std::string(bytes + sizeof(double) * (record.monitor_state.size() + 1));
  return record;
}

std::string checkpoint_prefix(const PoreOptions& options, const std::string& fix_id) {
  return options.checkpoint_prefix.empty() ? fix_id + ".fluid" : options.checkpoint_prefix;
}

std::string checkpoint_path(const std::string& prefix, long long step) {
  return prefix + "." + std::to_string(step);
}

}  // namespace lbm_pore
