// SPDX-License-Identifier: Apache-2.0
// The two files RSI runs on, as the controller reads them: the RSI context (NAME.rsi.xml: the
// signal-flow objects, their input wiring and parameters) and the Ethernet config its ETHERNET
// object names (the PC's address, the datagrams' Type, and the SEND and RECEIVE elements). Read
// with expat (xml_tree.h); every error names the file and line (docs/rsi.md, "Files"). Set-up only:
// any thread, allocates.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "rsi/xml_tree.h"

namespace xmate::rsi {

// ---- Ethernet config ------------------------------------------------------------------------------

enum class ValueType { kBool, kString, kLong, kDouble };
const char* toString(ValueType type);  // "BOOL", "STRING", "LONG", "DOUBLE"

// One SEND or RECEIVE element. A TAG "Name.Attr" is attribute Attr of the datagram element <Name>;
// a TAG without a dot is the text of <Name>. Built-in values (INDX="INTERNAL", TAG "DEF_...") lose
// their prefix in the datagram: DEF_RIst -> <RIst X=".." .../>, DEF_Delay -> <Delay D=".."/>.
struct Channel {
  std::string tag;        // as written, e.g. "AK.A1", "DEF_RIst", "Digout.o1"
  std::string element;    // the datagram element, e.g. "AK", "RIst"
  std::string attribute;  // e.g. "A1"; empty for a text element
  ValueType type = ValueType::kDouble;
  int index = 0;          // the ETHERNET object's channel 1..64; 0 for INTERNAL
  bool hold_on = false;   // RECEIVE: keep the last value when an answer is late
  int line = 0;           // in the file
  bool internal() const { return index == 0; }
};

struct EthernetConfig {
  std::string path;
  std::string ip;                  // IP_NUMBER as written
  bool ip_is_placeholder = false;  // not an IPv4 address (samples often hold text): bind to all
  uint16_t port = 0;               // the PC's port
  std::string sentype;             // the Type attribute of both datagrams
  bool only_send = false;          // the robot expects no answers
  std::vector<Channel> send;       // robot -> PC, in file order
  std::vector<Channel> receive;    // PC -> robot, in file order
};

// The built-in SEND values (DEF_ tags with INDX="INTERNAL"), and the built-in RECEIVE values.
inline constexpr const char* kBuiltInSend[] = {"DEF_RIst",  "DEF_RSol",  "DEF_AIPos", "DEF_ASPos", "DEF_EIPos",
                                               "DEF_ESPos", "DEF_MACur", "DEF_MECur", "DEF_Delay", "DEF_Tech"};
inline constexpr const char* kBuiltInReceive[] = {"DEF_EStr", "DEF_Tech"};

// Throws ConfigError: missing CONFIG / IP_NUMBER / PORT / SENTYPE, a PORT outside 1..65535, an
// unknown TYPE, an INDX outside 1..64 (or not INTERNAL), INTERNAL with a tag that is not a built-in
// value, a TAG twice in SEND or in RECEIVE, a dotted TAG whose parts disagree in TYPE, a bad HOLDON.
EthernetConfig readEthernetConfig(const std::string& path);
EthernetConfig parseEthernetConfig(std::string_view text, const std::string& name);

// ---- RSI context ----------------------------------------------------------------------------------

struct Input {
  int in_index = 0;        // this object's input, 1-based
  std::string out_object;  // the ObjID whose output feeds it
  int out_index = 0;       // that object's output, 1-based
};

struct Parameter {
  std::string name;
  std::string id;     // ParamID: repeats within an object in real files; look parameters up by name
  std::string value;  // ParamValue as written
};

struct Object {
  std::string type;  // ObjType, e.g. "ETHERNET", "AXISCORR"
  int type_id = 0;   // ObjTypeID (0 when absent)
  std::string id;    // ObjID, e.g. "AXISCORR1"
  std::vector<Input> inputs;
  std::vector<Parameter> parameters;
  int line = 0;
  // The value of the first parameter of that name, or nullptr.
  const std::string* parameter(std::string_view name) const;
};

struct Context {
  std::string path;
  std::vector<Object> objects;  // in file order
  const Object* find(std::string_view object_id) const;
  // The ETHERNET object (the first, if several), or nullptr.
  const Object* ethernet() const;
  // The Ethernet config file the ETHERNET object names, in the context's folder.
  std::string ethernetConfigPath() const;
};

// The number in an object's parameter `name` (a decimal in the C locale's forms, "+5", "-2.5"), or
// `fallback` when the object does not have it. Throws ConfigError "FILE:LINE: OBJID (TYPE):
// parameter NAME="..." is not a number; ..." when it is there but not a finite number.
double numberParameter(const Context& context, const Object& object, std::string_view name, double fallback);

// Throws ConfigError: an object without ObjType or ObjID, an ObjID twice, an input wired to an
// object that does not exist or with a non-positive index, no ETHERNET object, an ETHERNET object
// without ConfigFile.
Context readContext(const std::string& path);
Context parseContext(std::string_view text, const std::string& name);

// The RSI contexts (NAME.rsi.xml) in the directory of `ethernet_config_path` whose ETHERNET object
// names that file -- the context the robot runs, when only its Ethernet config was given. Files
// that cannot be read are skipped. Any thread; reads files.
std::vector<std::string> contextsNaming(const std::string& ethernet_config_path);

}  // namespace xmate::rsi
