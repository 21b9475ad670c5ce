// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the RSI datagram codec (rsi/codec.h) on a config with every kind of SEND value
// (built-in, attributes, text, each TYPE). Any input is either decoded or refused with a reason --
// never a crash or a hang -- and the answer to a decoded one is a complete <Sen> under 1 KB that
// echoes its IPOC and that the simulated KRC's SenDecoder reads back. The KRC's side reads any
// input too (as a <Sen>).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "rsi/codec.h"
#include "rsi/config.h"

namespace {

constexpr std::string_view kConfig = R"(<ROOT><CONFIG><IP_NUMBER>127.0.0.1</IP_NUMBER><PORT>49152</PORT>
<SENTYPE>ImFree</SENTYPE><ONLYSEND>FALSE</ONLYSEND></CONFIG>
<SEND><ELEMENTS>
<ELEMENT TAG="DEF_RIst" TYPE="DOUBLE" INDX="INTERNAL"/><ELEMENT TAG="DEF_AIPos" TYPE="DOUBLE" INDX="INTERNAL"/>
<ELEMENT TAG="DEF_Delay" TYPE="LONG" INDX="INTERNAL"/><ELEMENT TAG="DEF_Tech.C1" TYPE="DOUBLE" INDX="INTERNAL"/>
<ELEMENT TAG="In.b" TYPE="BOOL" INDX="1"/><ELEMENT TAG="Msg" TYPE="STRING" INDX="2"/><ELEMENT TAG="Count" TYPE="LONG" INDX="3"/>
</ELEMENTS></SEND>
<RECEIVE><ELEMENTS>
<ELEMENT TAG="DEF_EStr" TYPE="STRING" INDX="INTERNAL"/><ELEMENT TAG="AK.A1" TYPE="DOUBLE" INDX="1" HOLDON="1"/>
<ELEMENT TAG="Stop" TYPE="BOOL" INDX="2"/>
</ELEMENTS></RECEIVE></ROOT>)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const xmate::rsi::EthernetConfig config = xmate::rsi::parseEthernetConfig(kConfig, "fuzz config");
  static xmate::rsi::RobDecoder decoder(config);
  static xmate::rsi::SenEncoder encoder(config);
  static xmate::rsi::SenDecoder krc_side(config);
  krc_side.decode({reinterpret_cast<const char*>(data), size});
  if (!decoder.decode({reinterpret_cast<const char*>(data), size})) return 0;
  encoder.set(encoder.slot("AK", "A1"), decoder.value(decoder.slot("AIPos", "A1")));
  encoder.setText(encoder.slot("EStr"), decoder.text(decoder.slot("Msg")));
  char out[xmate::rsi::kMaxSenBytes];
  const size_t n = encoder.encode(decoder.ipocText(), out, sizeof out);
  if (n == 0 || n >= xmate::rsi::kMaxSenBytes) std::abort();  // a decoded IPOC always fits
  if (std::string_view(out, n).find(decoder.ipocText()) == std::string_view::npos) std::abort();
  if (!krc_side.decode({out, n}) || krc_side.ipocText() != decoder.ipocText()) std::abort();
  return 0;
}
