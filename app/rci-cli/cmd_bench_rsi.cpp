// SPDX-License-Identifier: Apache-2.0
// rci-cli bench rsi: what one RSI cycle costs the PC -- parse the <Rob>, publish it, call back,
// compose the <Sen>, send it -- on generated KRC datagrams for the sample Ethernet config, against
// a tinyxml2 DOM parse + compose of the same datagrams and a raw sendto, measured in the same run.
#include <tinyxml2.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "bench_stats.h"
#include "cli.h"
#include "net/clock.h"
#include "net/seqlock.h"
#include "net/udp_socket.h"
#include "rsi/codec.h"
#include "rsi/config.h"
#include "rsi/link.h"
#include "rsi_sample_config.h"  // kSampleEthernetConfig: resources/rsi/RSI_EthernetConfig.xml, compiled in

namespace rci_cli {
namespace {

using namespace xmate;

constexpr size_t kDatagrams = 1000;                // distinct <Rob> datagrams, replayed in turn
constexpr uint64_t kFirstIpoc = 4'294'967'000ull;  // crosses 2^32 after 74 cycles: 64-bit IPOCs

// One value as a KRC writes it: mostly "%.6f" ("10.000000"), some "%.4f", now and then a tiny
// number in exponent form ("1e-05") or a negative zero ("-0.000000").
std::string number(double v, size_t k, size_t s) {
  char buf[48];
  const size_t pick = (k * 7 + s * 3) % 23;
  if (pick == 0) return "-0.000000";
  if (pick == 1) {
    std::snprintf(buf, sizeof buf, "%g", 1e-5 * double(1 + (k + s) % 9));
    return buf;
  }
  std::snprintf(buf, sizeof buf, pick % 5 == 2 ? "%.4f" : "%.6f", v);
  return buf;
}

// A plausible value of slot s in cycle k (the arm moving slowly through its range).
double plausible(const rsi::Slot& slot, size_t k, size_t s) {
  const double t = double(k) * 0.004;  // 4 ms cycles
  const double wave = std::sin(0.7 * t + double(s));
  const std::string& e = slot.element;
  const std::string& a = slot.attribute;
  if (e == "RIst" || e == "RSol") {
    if (a == "X") return 445.5 + 120 * wave;
    if (a == "Y") return -35.25 + 200 * wave;
    if (a == "Z") return 880 + 60 * wave;
    return (a == "B" ? 0.0 : 179.5) + 15 * wave;
  }
  if (e == "AIPos" || e == "ASPos") {
    static const double home[6] = {0, -90, 90, 0, 90, 0};
    return home[(a.back() - '1') % 6] + 25 * wave;
  }
  if (e == "MACur") return 2.5 * wave;
  if (e == "Delay") return double(k % 97 == 0);
  if (e == "Override") return 100;
  if (e == "Status") return 3;
  return 40 * wave;  // gear torques and other channels, Nm
}

// The k-th <Rob> for this layout: elements in config order, attributes together, one per line.
std::string makeRob(const rsi::RobDecoder& decoder, const std::string& sentype, size_t k) {
  const auto& layout = decoder.layout();
  std::string rob = "<Rob Type=\"" + sentype + "\">\n";
  for (size_t s = 0; s < layout.size();) {
    const rsi::Slot& first = layout[s];
    auto text = [&](size_t i) {
      const rsi::Slot& slot = layout[i];
      const double v = plausible(slot, k, i);
      if (slot.type == rsi::ValueType::kLong || slot.type == rsi::ValueType::kBool)
        return std::to_string(long(std::lround(v)));
      if (slot.type == rsi::ValueType::kString) return std::string("ok");
      return number(v, k, i);
    };
    if (first.attribute.empty()) {
      rob += "<" + first.element + ">" + text(s) + "</" + first.element + ">\n";
      ++s;
      continue;
    }
    rob += "<" + first.element;
    for (; s < layout.size() && layout[s].element == first.element && !layout[s].attribute.empty(); ++s)
      rob += " " + layout[s].attribute + "=\"" + text(s) + "\"";
    rob += " />\n";
  }
  rob += "<IPOC>" + std::to_string(kFirstIpoc + 4 * k) + "</IPOC>\n</Rob>";
  return rob;
}

// The callback both sides run: a small axis correction from the measured A1, as a controller would.
rsi::Correction correctionFor(double a1) {
  rsi::Correction c;
  c.kind = rsi::Correction::Kind::kAxis;
  c.values = {1e-3 * a1, 0, 0, 0, 0, -1e-3 * a1};
  return c;
}

// The reference: the same work done the common way, with a DOM (tinyxml2). The documents and the
// printer are kept from cycle to cycle (the DOM at its best); elements are looked up by name once
// per element group, numbers read with strtod, written with the same "%.4f".
class DomReference {
 public:
  DomReference(const rsi::EthernetConfig& config, const rsi::RobDecoder& decoder, const rsi::SenEncoder& encoder,
               int a1_slot)
      : sentype_(config.sentype), rob_layout_(decoder.layout()), sen_layout_(encoder.layout()), a1_slot_(a1_slot) {
    values_.assign(rob_layout_.size(), 0.0);
    sen_values_.assign(sen_layout_.size(), 0.0);
    for (size_t i = 0; i < 6; ++i) axis_[i] = encoder.slot("AK", std::string(1, 'A').append(std::to_string(i + 1)));
  }

  // Parse + callback + compose; the answer in answer()/answerSize(). False if the datagram was refused.
  bool cycle(std::string_view rob) {
    const int64_t t0 = net::monotonicNs();
    if (in_.Parse(rob.data(), rob.size()) != tinyxml2::XML_SUCCESS) return false;
    const tinyxml2::XMLElement* root = in_.RootElement();
    if (root == nullptr || std::strcmp(root->Name(), "Rob") != 0) return false;
    const tinyxml2::XMLElement* element = nullptr;
    const std::string* element_name = nullptr;
    for (size_t s = 0; s < rob_layout_.size(); ++s) {
      const rsi::Slot& slot = rob_layout_[s];
      if (element_name == nullptr || *element_name != slot.element) {
        element = root->FirstChildElement(slot.element.c_str());
        element_name = &slot.element;
      }
      if (element == nullptr) continue;
      const char* text = slot.attribute.empty() ? element->GetText() : element->Attribute(slot.attribute.c_str());
      if (text != nullptr) values_[s] = std::strtod(text, nullptr);
    }
    const tinyxml2::XMLElement* ipoc = root->FirstChildElement("IPOC");
    if (ipoc == nullptr || ipoc->GetText() == nullptr) return false;
    ipoc_ = ipoc->GetText();
    parse_ns_ = net::monotonicNs() - t0;  // parsed and read: the part that compares with RobDecoder::decode

    const rsi::Correction c = correctionFor(values_[size_t(a1_slot_)]);
    for (size_t i = 0; i < 6; ++i)
      if (axis_[i] >= 0) sen_values_[size_t(axis_[i])] = c.values[i];

    const int64_t composing = net::monotonicNs();
    out_.Clear();
    tinyxml2::XMLElement* sen = out_.NewElement("Sen");
    sen->SetAttribute("Type", sentype_.c_str());
    out_.InsertEndChild(sen);
    tinyxml2::XMLElement* group = nullptr;
    char buf[48];
    for (size_t s = 0; s < sen_layout_.size(); ++s) {
      const rsi::Slot& slot = sen_layout_[s];
      if (group == nullptr || slot.attribute.empty() || slot.element != group->Name()) {
        group = out_.NewElement(slot.element.c_str());
        sen->InsertEndChild(group);
      }
      const double v = sen_values_[s];
      if (slot.type == rsi::ValueType::kString)
        buf[0] = '\0';
      else if (slot.type == rsi::ValueType::kDouble)
        std::snprintf(buf, sizeof buf, "%.4f", v);
      else
        std::snprintf(buf, sizeof buf, "%ld", long(std::lround(v)));
      if (slot.attribute.empty())
        group->SetText(buf);
      else
        group->SetAttribute(slot.attribute.c_str(), buf);
    }
    tinyxml2::XMLElement* answer_ipoc = out_.NewElement("IPOC");
    answer_ipoc->SetText(ipoc_.c_str());
    sen->InsertEndChild(answer_ipoc);
    printer_.ClearBuffer();
    out_.Print(&printer_);
    compose_ns_ = net::monotonicNs() - composing;
    return true;
  }
  const char* answer() const { return printer_.CStr(); }
  size_t answerSize() const { return size_t(printer_.CStrSize() - 1); }
  double value(size_t s) const { return values_[s]; }
  const std::string& ipoc() const { return ipoc_; }
  int64_t parseNs() const { return parse_ns_; }
  int64_t composeNs() const { return compose_ns_; }

 private:
  std::string sentype_;
  const std::vector<rsi::Slot>& rob_layout_;
  const std::vector<rsi::Slot>& sen_layout_;
  int a1_slot_;
  std::array<int, 6> axis_{};
  std::vector<double> values_, sen_values_;
  std::string ipoc_;
  int64_t parse_ns_ = 0, compose_ns_ = 0;
  tinyxml2::XMLDocument in_, out_;
  tinyxml2::XMLPrinter printer_{nullptr, true};  // compact: no indentation
};

}  // namespace

int runBenchRsi(long cycles) {
  const rsi::EthernetConfig config = rsi::parseEthernetConfig(kSampleEthernetConfig, "RSI_EthernetConfig.xml");
  rsi::RobDecoder decoder(config);
  rsi::SenEncoder encoder(config, 4);
  const int a1 = decoder.slot("AIPos", "A1");
  std::array<int, 6> axis_slots{};
  for (size_t i = 0; i < 6; ++i) axis_slots[i] = encoder.slot("AK", std::string("A") + char('1' + i));
  if (a1 < 0 || axis_slots[0] < 0) {
    std::fprintf(stderr, "rci-cli: bench rsi: the sample config has no DEF_AIPos or no AK.A1; it was changed\n");
    return 1;
  }

  std::vector<std::string> robs(kDatagrams);
  size_t shortest = SIZE_MAX, longest = 0;
  for (size_t k = 0; k < kDatagrams; ++k) {
    robs[k] = makeRob(decoder, config.sentype, k);
    shortest = std::min(shortest, robs[k].size());
    longest = std::max(longest, robs[k].size());
  }

  // The robot: a socket the answers go to, drained between measurements (as in bench client).
  net::UdpSocket sink;
  sink.bind("127.0.0.1", 0);
  sink.setBufferSizes(4 << 20, 4 << 20);
  const net::Endpoint robot = net::makeEndpoint("127.0.0.1", sink.localPort());
  net::UdpSocket socket;
  socket.bind("127.0.0.1", 0);

  // What the link keeps per cycle (link.h): the newest values for other threads, and the callback.
  auto latest = std::make_unique<net::Seqlock<rsi::RobSample>>();
  const rsi::Link::Callback callback = [a1](const rsi::RobDecoder& rob) { return correctionFor(rob.value(a1)); };
  DomReference dom(config, decoder, encoder, a1);

  // Both parsers must read the same values and IPOC from every datagram (checked once, untimed).
  size_t disagreements = 0;
  for (const std::string& rob : robs) {
    if (!decoder.decode(rob) || !dom.cycle(rob)) {
      std::fprintf(stderr, "rci-cli: bench rsi: a generated datagram was refused (%s):\n%s\n", decoder.reason(),
                   rob.c_str());
      return 1;
    }
    for (size_t s = 0; s < decoder.layout().size(); ++s)
      if (decoder.value(int(s)) != dom.value(s)) ++disagreements;
    if (decoder.ipocText() != dom.ipoc()) ++disagreements;
  }

  const size_t n = size_t(cycles);
  std::vector<int64_t> ours_xml(n), ours_cycle(n), dom_xml(n), dom_cycle(n), raw_send(n);
  std::vector<int64_t> ours_parse(n), ours_compose(n), dom_parse(n), dom_compose(n);  // parts of the above
  char out[rsi::kMaxSenBytes];
  char raw[rsi::kMaxSenBytes] = {};
  size_t answer_bytes = 0, dom_answer_bytes = 0;
  uint64_t refused = 0, send_failures = 0;
  // Where each datagram is "received" before a cycle, as recvfrom leaves it in the link's buffer
  // (and in the cache): neither side is timed reading it cold, or warm from the other's parse.
  std::vector<char> received(rsi::kMaxDatagramBytes);
  auto receive = [&](const std::string& datagram) {
    std::memcpy(received.data(), datagram.data(), datagram.size());
    return std::string_view(received.data(), datagram.size());
  };
  for (size_t k = 0; k < n; ++k) {
    if (k % 256 == 0) drain(sink);
    std::string_view rob = receive(robs[k % kDatagrams]);

    // Ours, as rsi::Link runs a cycle: decode, publish, call back, set the corrections, encode, send.
    int64_t t0 = net::monotonicNs();
    if (!decoder.decode(rob)) ++refused;
    const int64_t parsed = net::monotonicNs();
    rsi::RobSample sample;
    sample.ipoc = decoder.ipoc();
    sample.received_ns = t0;
    sample.session = 1;
    sample.count = uint32_t(std::min(decoder.layout().size(), rsi::kMaxSlots));
    for (uint32_t i = 0; i < sample.count; ++i) sample.values[i] = decoder.value(int(i));
    latest->store(sample);
    const rsi::Correction c = callback(decoder);
    for (size_t i = 0; i < 6; ++i)
      if (axis_slots[i] >= 0) encoder.set(axis_slots[i], c.values[i]);
    const int64_t composing = net::monotonicNs();
    answer_bytes = encoder.encode(decoder.ipocText(), out, sizeof out);
    int64_t t1 = net::monotonicNs();
    ours_parse[k] = parsed - t0;
    ours_compose[k] = t1 - composing;
    if (socket.sendTo(robot, out, answer_bytes) != long(answer_bytes)) ++send_failures;
    int64_t t2 = net::monotonicNs();
    ours_xml[k] = t1 - t0;
    ours_cycle[k] = t2 - t0;

    // The DOM reference: the same work and the same send.
    rob = receive(robs[k % kDatagrams]);
    t0 = net::monotonicNs();
    if (!dom.cycle(rob)) ++refused;
    t1 = net::monotonicNs();
    dom_parse[k] = dom.parseNs();
    dom_compose[k] = dom.composeNs();
    dom_answer_bytes = dom.answerSize();
    if (socket.sendTo(robot, dom.answer(), dom_answer_bytes) != long(dom_answer_bytes)) ++send_failures;
    t2 = net::monotonicNs();
    dom_xml[k] = t1 - t0;
    dom_cycle[k] = t2 - t0;

    // A raw sendto of our answer's size.
    t0 = net::monotonicNs();
    if (socket.sendTo(robot, raw, answer_bytes) != long(answer_bytes)) ++send_failures;
    t1 = net::monotonicNs();
    raw_send[k] = t1 - t0;
  }
  if (refused > 0 || send_failures > 0) {
    std::fprintf(stderr, "rci-cli: bench rsi: %llu datagrams refused, %llu sends failed; the numbers would be wrong\n",
                 (unsigned long long)refused, (unsigned long long)send_failures);
    return 1;
  }

  const Percentiles op = percentilesOf(ours_parse), oe = percentilesOf(ours_compose), dp = percentilesOf(dom_parse),
                    de = percentilesOf(dom_compose);
  const Percentiles ox = percentilesOf(ours_xml), oc = percentilesOf(ours_cycle), dx = percentilesOf(dom_xml),
                    dc = percentilesOf(dom_cycle), rs = percentilesOf(raw_send);
  std::printf("rci-cli bench rsi: %ld cycles, one thread, loopback; %zu generated <Rob> datagrams of %zu-%zu bytes "
              "(%zu values) for the sample config, <Sen> of %zu bytes\n",
              cycles, kDatagrams, shortest, longest, decoder.layout().size(), answer_bytes);
  printPercentilesHeader();
  printPercentilesRow("ours: parse <Rob> + publish + callback + compose <Sen>", ox);
  printPercentilesRow("ours: the whole cycle, with the sendto", oc);
  printPercentilesRow("reference: tinyxml2 DOM parse + callback + compose", dx);
  printPercentilesRow("reference: tinyxml2 DOM, with the sendto", dc);
  printPercentilesRow("  of which ours: parse <Rob> (RobDecoder::decode)", op);
  printPercentilesRow("  of which ours: compose <Sen> (SenEncoder::encode)", oe);
  printPercentilesRow("  of which DOM: parse <Rob> and read its values", dp);
  printPercentilesRow("  of which DOM: compose <Sen> and print it", de);
  char label[64];
  std::snprintf(label, sizeof label, "reference: raw sendto of %zu bytes", answer_bytes);
  printPercentilesRow(label, rs);
  std::printf("  ours vs DOM (medians): %.1fx faster without the send, %.1fx with it (parse %.1fx, compose %.1fx)\n",
              dx.median / ox.median, dc.median / oc.median, dp.median / op.median, de.median / oe.median);
  std::printf("  ours vs raw sendto (medians): the whole cycle is %.1fx a raw sendto (%.3f us above it)\n",
              oc.median / rs.median, oc.median - rs.median);
  std::printf("  targets: median <= 20 us per cycle -> %s; >= 5x faster than the DOM (without the send) -> %s\n",
              oc.median <= 20.0 ? "met" : "NOT met", dx.median >= 5.0 * ox.median ? "met" : "NOT met");
  std::printf("  agreement: both parsers read the same %zu values and IPOC from all %zu datagrams%s; DOM <Sen> %zu "
              "bytes\n",
              decoder.layout().size(), kDatagrams,
              disagreements == 0 ? "" : (" -- NOT: " + std::to_string(disagreements) + " differ").c_str(),
              dom_answer_bytes);
  return disagreements == 0 ? 0 : 1;
}

}  // namespace rci_cli
