// SPDX-License-Identifier: Apache-2.0
// rci-cli's commands, their options, and the command-line helpers they share (CLI11, args.cpp).
// Each command returns the process exit code: 0 success, 1 failure at run time, 2 bad arguments
// (CLI11's parse errors and UsageError).
#pragma once

#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <xmate/types.h>

namespace xmate::rsi {
class Link;
}  // namespace xmate::rsi
namespace xmate::arm {
class JointStream;
}  // namespace xmate::arm

namespace rci_cli::soak {
struct SoakOptions;
}  // namespace rci_cli::soak

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace rci_cli {

// Bad command-line arguments found after parsing: main() prints the message and the command's
// usage, and exits with 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct HostPort {
  std::string host;
  uint16_t port = 1337;
};

// What --robot names: the in-process simulator ("sim") or a controller at HOST:PORT.
struct RobotTarget {
  bool in_process = false;  // "sim": an in-process xMate simulator
  HostPort address;         // an xMate controller
  // A KUKA over RSI: "rsi:ETHERNET.xml" (rsi_config: the Ethernet config's path), or "rsi-sim" (an
  // in-process simulated KRC; rsi_config empty).
  bool rsi = false;
  std::string rsi_config;
};

// The one parser of --robot's value, for every command that takes it: "sim" (when sim_allowed),
// "HOST:PORT" or "HOST" (port 1337), and with rsi_allowed "rsi:FILE" (and "rsi-sim" when
// sim_allowed too). Throws UsageError saying what was wrong and what to write.
RobotTarget parseRobotTarget(const std::string& text, bool sim_allowed, bool rsi_allowed = false);

// Options shared by the commands, with their checks (a bad value is a CLI11 ValidationError whose
// message says what the option takes and what it got):
//   --robot sim|HOST:PORT (or HOST:PORT alone), parsed by parseRobotTarget into `target`;
CLI::Option* addRobotOption(CLI::App& command, RobotTarget& target, bool sim_allowed, const std::string& help,
                            bool rsi_allowed = false);
//   --model NAME (or another name, e.g. the positional NAME of `model`), one of the four model names;
CLI::Option* addModelOption(CLI::App& command, xmate::XmateType& type, const std::string& help,
                            const std::string& name = "--model");
//   a whole number in [lo, hi].
CLI::Option* addWholeNumberOption(CLI::App& command, const std::string& name, long& value, long lo, long hi,
                                  const std::string& help);
//   a decimal option from lo to hi; a value outside says "NAME takes MEANING, got 'X'"
//   (meaning e.g. "a speed override from 0.1 to 1.0 (e.g. 0.5 = 50 %)").
CLI::Option* addDecimalOption(CLI::App& command, const std::string& name, double& value, double lo, double hi,
                              const std::string& meaning, const std::string& help);
// "'xmate7_pro' -> XMATE7_PRO"; UsageError listing the four names otherwise.
xmate::XmateType parseModel(const std::string& text);

// Where the PC listens for a KUKA's RSI datagrams (--bind, --port).
struct RsiListen {
  std::string bind_ip;  // --bind ("": the config's IP_NUMBER, or every address if it is a placeholder)
  long port = -1;       // --port (-1: the config's PORT; 0: a free port, announced)
};
// --bind ADDR and --port P, for `state` and `run` over RSI.
void addRsiListenOptions(CLI::App& command, RsiListen& listen);
//   --context FILE (help: `context_help`) and --cycle-ms 4|12, for commands that drive a KUKA.
void addRsiContextOptions(CLI::App& command, std::string& context_path, int& cycle_ms, const std::string& context_help);

struct StateOptions {
  RobotTarget robot;  // never in_process; rsi: a KUKA arm over RSI (cmd_state_rsi.cpp), never rsi-sim
  long count = 0;     // 0: until interrupted
  xmate::XmateType model = xmate::XMATE7_PRO;
  std::string model_name;  // --model as written ("": left out), checked by checkStateOptions
  RsiListen listen;
  long wait_s = 60;        // --wait: give up when no <Rob> comes for this long
  bool bind_given = false, port_given = false, wait_given = false;
};
// A KUKA model of the robot specs (model::findRobotSpec): the arms that speak RSI.
bool isRsiModel(const std::string& name);
// "unknown model 'X'; choose one of: ... (xMate, ...) or ... (KUKA, ...)".
std::string unknownModelText(const std::string& name);
// --model NAME: any model of either family, by name (checked: unknownModelText).
CLI::Option* addModelNameOption(CLI::App& command, std::string& name, const std::string& help);
// The checks that need more than one option (--model against --robot's kind, --bind/--port/--wait
// only with rsi:); fills options.model. Throws UsageError saying what to write instead.
void checkStateOptions(StateOptions& options);
// The options of `state`: --robot HOST:PORT|rsi:FILE (required), --count, --model, and for RSI --bind,
// --port, --wait (whether those were given is read from the command after parsing).
void addStateOptions(CLI::App& state, StateOptions& options);

struct RunOptions {
  std::string program_path;
  RobotTarget robot;
  std::string model_name;    // --model ("": the program's)
  RsiListen listen;          // RSI: where to listen
  std::string context_path;  // RSI: --context, the RSI context (its AXISCORR limits); "": found beside the config
  int cycle_ms = 4;          // RSI: --cycle-ms, the robot's RSI cycle (4 with #IPO_FAST, else 12)
  bool rsi_options_given = false;  // any of --bind, --port, --context, --cycle-ms
  double speed = 1.0;
  std::string report_path;
  bool fast = false;  // in-process simulator on the lock-step clock (faster than real time)
};

struct LoopOptions {
  RobotTarget robot{true, {}, false, {}};
  long cycles = 10'000;
  bool lockstep = false;
  xmate::XmateType type = xmate::XMATE7_PRO;
};

struct FtOptions {
  std::string host;                 // the sensor's IPv4 address
  uint16_t port = 49152;            // RDT's port
  long count = 0;                   // 0: until interrupted
  double counts_per_unit = 1e6;     // counts per N and per Nm (the sensor's configuration)
};
// "HOST" or "HOST:PORT" (port 49152 if left out) into options.host/port; UsageError otherwise.
void parseSensorAddress(const std::string& text, FtOptions& options);
//   --sensor HOST[:PORT], parsed by parseSensorAddress.
CLI::Option* addSensorOption(CLI::App& command, FtOptions& options);

// The RSI context beside the Ethernet config `config_path` that names it; std::runtime_error saying
// to give --context when there is none or more than one.
std::string contextNaming(const std::string& config_path);
// Waits (at most a minute, or until `interrupted`) until the robot sends; prints what to do meanwhile.
// std::runtime_error saying what to check when it does not.
void waitForRsi(const xmate::rsi::Link& link, const xmate::arm::JointStream& stream, const std::string& where,
                const std::atomic<bool>& interrupted);

struct GuideOptions {
  RobotTarget robot;              // rsi:ETHERNET.xml
  std::string model_name;         // --model, a KUKA
  FtOptions sensor;               // --sensor, --counts-per-unit
  RsiListen listen;
  std::string context_path;       // "": found beside the config
  int cycle_ms = 4;
  std::string axes = "translation";  // translation | rotation | free
  double tool_mass = 0;           // kg
  std::vector<double> tool_center{0, 0, 0};  // m, flange frame
  double max_speed = 0.25;        // m/s
  long seconds = 0;               // 0: until Ctrl-C
};

int runModel(xmate::XmateType type);         // rci-cli [model NAME]
int runFt(const FtOptions& options);         // rci-cli ft --sensor HOST[:PORT] [--count N] [--counts-per-unit C]
int runState(const StateOptions& options);   // rci-cli state --robot HOST:PORT [--count N] [--model NAME]
// rci-cli state --robot rsi:ETHERNET.xml --model NAME [--bind ADDR] [--port P] [--count N] [--wait S]
int runStateRsi(const StateOptions& options);
int runDoctor();                             // rci-cli doctor
int runBenchLoop(const LoopOptions& options);  // rci-cli bench loop [--robot sim|HOST:PORT] [--cycles N] [--lockstep] [--model NAME]
int runBenchClient(long cycles);             // rci-cli bench client [--cycles N]
int runBenchRsi(long cycles);                // rci-cli bench rsi [--cycles N]
int runBenchPath(double seconds, int rounds);  // rci-cli bench path [--seconds S] [--rounds N]
// rci-cli bench soak [--motions N] [--loss PERCENT] [--seed N] [--no-burners] [--lockstep] [--json];
// exits 1 when a motion failed.
int runBenchSoak(const soak::SoakOptions& options, bool json);
int runRun(const RunOptions& options);
// rci-cli guide --robot rsi:ETHERNET.xml --model NAME --sensor HOST[:PORT] [--axes A] [--tool-mass KG] ...
int runGuide(const GuideOptions& options);       // rci-cli run PROGRAM.json --robot sim|HOST:PORT [--model NAME] [--speed R] [--report FILE] [--fast]

}  // namespace rci_cli
