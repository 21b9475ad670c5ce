// SPDX-License-Identifier: Apache-2.0
// rsi::DigitalIoMap and rsi::DigitalIo (digital_io.h): the context's DIGIN/DIGOUT wiring to the
// ETHERNET object, and setting and reading those signals through the link.
#include "rsi/digital_io.h"

#include <cmath>
#include <stdexcept>

#include "model/signal_names.h"

namespace xmate::rsi {
namespace {

int firstSignal(const Context& context, const Object& object) {
  const double index = numberParameter(context, object, "Index", 1);
  if (index < 1 || index != std::floor(index) || index > 1e6)
    throw ConfigError(context.path + ":" + std::to_string(object.line) + ": " + object.id + " (" + object.type +
                      "): Index " + object.parameter("Index")->c_str() +
                      " is not an input/output number; give the first one, from 1");
  return int(index);
}

const Channel* channelWithIndex(const std::vector<Channel>& channels, int index) {
  for (const Channel& c : channels)
    if (!c.internal() && c.index == index) return &c;
  return nullptr;
}

DigitalSignal signalOf(int number, const Channel& channel, const Object& object) {
  return {number, channel.tag, channel.element, channel.attribute, object.id};
}

const DigitalSignal* find(const std::vector<DigitalSignal>& signals, int number) {
  for (const DigitalSignal& s : signals)
    if (s.signal == number) return &s;
  return nullptr;
}

// A KUKA's name of an input or output: "$IN[3]", "$OUT[3]".
std::string nameOf(int signal, bool output) {
  return output ? model::doName(model::RobotFamily::kKuka, signal) : model::diName(model::RobotFamily::kKuka, signal);
}

std::string wiredList(const std::vector<DigitalSignal>& signals, bool output) {
  if (signals.empty()) return std::string("no ") + (output ? "$OUT" : "$IN") + " is wired to the PC";
  std::string list;
  for (const DigitalSignal& s : signals) list += (list.empty() ? "" : ", ") + nameOf(s.signal, output);
  return "wired to the PC: " + list;
}

}  // namespace

const DigitalSignal* DigitalIoMap::input(int signal) const { return find(inputs, signal); }
const DigitalSignal* DigitalIoMap::output(int signal) const { return find(outputs, signal); }

DigitalIoMap digitalIoMap(const Context& context, const EthernetConfig& config) {
  DigitalIoMap map;
  const Object* ethernet = context.ethernet();
  if (!ethernet) return map;
  for (const Input& wire : ethernet->inputs) {  // robot -> PC
    const Object* from = context.find(wire.out_object);
    const Channel* channel = channelWithIndex(config.send, wire.in_index);
    if (!from || from->type != "DIGIN" || !channel) continue;
    const int number = firstSignal(context, *from) + wire.out_index - 1;
    if (!map.input(number)) map.inputs.push_back(signalOf(number, *channel, *from));
  }
  for (const Object& object : context.objects) {  // PC -> robot
    if (object.type != "DIGOUT") continue;
    for (const Input& wire : object.inputs) {
      const Channel* channel = channelWithIndex(config.receive, wire.out_index);
      if (wire.out_object != ethernet->id || !channel) continue;
      const int number = firstSignal(context, object) + wire.in_index - 1;
      if (!map.output(number)) map.outputs.push_back(signalOf(number, *channel, object));
    }
  }
  return map;
}

DigitalIo::DigitalIo(Link& link, DigitalIoMap map) : link_(link), map_(std::move(map)) {
  for (const DigitalSignal& s : map_.inputs) {
    input_slots_.push_back(link_.slot(s.element, s.attribute));
    if (input_slots_.back() < 0 || size_t(input_slots_.back()) >= kMaxSlots)
      throw std::invalid_argument("rsi::DigitalIo: the link's Ethernet config does not send " + s.tag);
  }
  for (const DigitalSignal& s : map_.outputs) {
    output_slots_.push_back(link_.receiveSlot(s.element, s.attribute));
    if (output_slots_.back() < 0)
      throw std::invalid_argument("rsi::DigitalIo: the link's Ethernet config does not receive " + s.tag);
  }
}

void DigitalIo::setOutput(int signal, bool level) {
  for (size_t i = 0; i < map_.outputs.size(); ++i)
    if (map_.outputs[i].signal == signal) return link_.setReceiveValue(output_slots_[i], level ? 1.0 : 0.0);
  throw std::out_of_range(nameOf(signal, true) + " is not wired to the PC in the RSI context (" +
                          wiredList(map_.outputs, true) +
                          "); wire an ETHERNET output to a DIGOUT input for it in RSI Visual");
}

bool DigitalIo::input(int signal) const {
  for (size_t i = 0; i < map_.inputs.size(); ++i) {
    if (map_.inputs[i].signal != signal) continue;
    RobSample sample;
    if (!link_.latest(sample))
      throw std::runtime_error("RSI is not running: no <Rob> datagram has arrived, so " + nameOf(signal, false) +
                               " is not known yet");
    return sample.values[size_t(input_slots_[i])] != 0.0;
  }
  throw std::out_of_range(nameOf(signal, false) + " is not wired to the PC in the RSI context (" +
                          wiredList(map_.inputs, false) +
                          "); wire a DIGIN output to an ETHERNET input for it in RSI Visual");
}

}  // namespace xmate::rsi
