// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the RSI config readers (rsi/config.h). The first byte chooses the reader (even:
// Ethernet config, odd: RSI context); the rest is the file. Any input must either parse or throw
// ConfigError -- never crash, hang or throw anything else.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "rsi/config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    if (data[0] % 2 == 0)
      (void)xmate::rsi::parseEthernetConfig(text, "fuzz.xml");
    else
      (void)xmate::rsi::parseContext(text, "fuzz.rsi.xml");
  } catch (const xmate::rsi::ConfigError&) {
  }
  return 0;
}
