// SPDX-License-Identifier: Apache-2.0
// guide::NetFtSource: an ATI Net F/T sensor (ft::NetFtClient) as the guide's wrench source. A
// reading whose status word reports a fault counts as no reading (the guide then stops: silent).
#pragma once

#include "ft/netft.h"
#include "guide/admittance.h"

namespace xmate::guide {

class NetFtSource : public WrenchSource {
 public:
  explicit NetFtSource(const ft::NetFtClient& client) : client_(client) {}
  bool read(std::array<double, 6>& wrench, int64_t& received_ns) const override {
    ft::Wrench w;
    if (!client_.latest(w) || w.status != 0) return false;
    wrench = w.values;
    received_ns = w.received_ns;
    return true;
  }

 private:
  const ft::NetFtClient& client_;
};

}  // namespace xmate::guide
