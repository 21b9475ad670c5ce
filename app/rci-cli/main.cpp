// SPDX-License-Identifier: Apache-2.0
// rci-cli: headless tools for xMate robots (docs/client.md) and KUKA arms over RSI (docs/rsi.md).
// Without arguments it describes the default model; subcommands read a robot's state live (RCI or
// RSI), check the machine's real-time setup, benchmark the 1 kHz loop and the client's and the RSI
// link's cost per cycle, soak motions under lost states, and run taught programs headless.
// The command line is CLI11's: a subcommand per tool, each with its generated --help.
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>
#include <xmate/exception.h>

#include "cli.h"
#include "net/realtime.h"
#include "soak/soak.h"

namespace {

using namespace rci_cli;

// The deepest subcommand the parser got to (the one whose usage to show with an error).
const CLI::App* selectedCommand(const CLI::App& app) {
  const CLI::App* at = &app;
  for (;;) {
    const auto chosen = at->get_subcommands();
    if (chosen.empty()) return at;
    at = chosen.front();
  }
}

std::string commandPath(const CLI::App* command) {
  std::string path;
  for (const CLI::App* c = command; c != nullptr; c = c->get_parent())
    path = c->get_name() + (path.empty() ? "" : " " + path);
  return path;
}

// "The following argument(s) was/were not expected: a b" -> the arguments.
std::vector<std::string> unexpectedArguments(const std::string& what) {
  std::vector<std::string> words;
  const auto colon = what.find(": ");
  std::string rest = colon == std::string::npos ? what : what.substr(colon + 2);
  for (size_t start = 0; start < rest.size();) {
    const auto space = rest.find(' ', start);
    words.push_back(rest.substr(start, space - start));
    if (space == std::string::npos) break;
    start = space + 1;
  }
  return words;
}

// CLI11's parse error as one line that says what was wrong (the usage that follows says what to do).
std::string explain(const CLI::ParseError& e, const CLI::App& app, const CLI::App* command) {
  const std::string what = e.what();
  const std::string name = command == &app ? "" : commandPath(command).substr(app.get_name().size() + 1);
  if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
    const std::string first = unexpectedArguments(what).front();
    if (!first.empty() && first[0] == '-')
      return (name.empty() ? "" : name + ": ") + "unknown option '" + first + "'";
    if (command == &app) return "unknown command '" + first + "' (known: model, state, run, guide, doctor, bench, ft, help)";
    if (name == "bench") return "unknown bench '" + first + "' (known: loop, client, rsi, path, soak)";
    return name + ": unexpected argument '" + first + "'";
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e)) return what.substr(0, what.find(':')) + " needs a value";
  if (dynamic_cast<const CLI::RequiredError*>(&e)) {
    if (name == "bench") {
      const auto rest = command->remaining();
      return rest.empty() ? "bench needs 'loop', 'client', 'rsi', 'path' or 'soak'"
                          : "unknown bench '" + rest.front() + "' (known: loop, client, rsi, path, soak)";
    }
    if (what.rfind("PROGRAM", 0) == 0) return "run needs a program file (PROGRAM.json)";
    if (what.rfind("--robot", 0) == 0)
      return name + (name == "run"     ? " needs --robot sim or --robot HOST:PORT"
                     : name == "state" ? " needs --robot HOST:PORT (an xMate) or --robot rsi:ETHERNET.xml (a KUKA over RSI)"
                                       : " needs --robot HOST:PORT");
    return name + ": " + what;
  }
  if (dynamic_cast<const CLI::ValidationError*>(&e)) {
    // "--cycles: takes a whole number ..." -> "--cycles takes a whole number ...",
    // "--robot: 'x:0': the port ..." -> "--robot 'x:0': the port ...".
    const auto colon = what.find(": ");
    if (colon != std::string::npos && (what.compare(colon + 2, 6, "takes ") == 0 || what.compare(colon + 2, 1, "'") == 0))
      return what.substr(0, colon) + " " + what.substr(colon + 2);
  }
  return what;
}

// bench soak's options as parsed: the seed, and --loss 0 switching the whole loss pattern off.
soak::SoakOptions soakOptions(soak::SoakOptions options, long seed) {
  options.seed = uint32_t(seed);
  if (options.loss_percent == 0) options.burst_states = options.burst_every_ms = 0;
  return options;
}

// The message, then the usage of the command it is about.
int usageError(const std::string& message, const CLI::App* command) {
  const std::string parents = command->get_parent() ? commandPath(command->get_parent()) : "";
  std::fprintf(stderr, "rci-cli: %s\n\n%s", message.c_str(), command->help(parents).c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Headless tools for ROKAE xMate robots and the simulator, and KUKA arms over RSI: a model's "
               "limits, a robot's live state, this machine's real-time fitness, loop, client and RSI link "
               "benchmarks, running taught programs. "
               "Without a command: the limits of the xMate Pro 7 (rci-cli model).",
               "rci-cli");
  app.footer("Exit status: 0 success, 1 failure at run time (the message says why), 2 bad arguments.\n"
             "rci-cli COMMAND --help describes a command.");
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.require_subcommand(0, 1);

  xmate::XmateType model_type = xmate::XMATE7_PRO;
  CLI::App* model = app.add_subcommand("model", "the published limits of a model (default xmate7_pro)");
  addModelOption(*model, model_type, "xmate3_pro, xmate7_pro, xmate3 or xmate7", "NAME");

  StateOptions state_options;
  CLI::App* state = app.add_subcommand("state", "live readout of a robot's state (joints, torques, TCP pose, "
                                                 "mode, error bits, command success rate); a KUKA's over RSI "
                                                 "(axes, pose, motor currents, Delay, IPOC, cycle time)");
  addStateOptions(*state, state_options);

  RunOptions run_options;
  CLI::App* run = app.add_subcommand("run", "run a taught program (docs/teach.md): pre-flight, then replay");
  run->add_option("PROGRAM", run_options.program_path, "the program file (rci-program JSON)")->required();
  addRobotOption(*run, run_options.robot, true,
                 "sim: an in-process simulator for the program's model on its real-time clock; HOST:PORT: a "
                 "controller or rci-sim; rsi:ETHERNET.xml: a KUKA over RSI (docs/rsi.md); rsi-sim: an in-process "
                 "simulated KRC for the program's KUKA model",
                 true)
      ->required();
  addModelNameOption(*run, run_options.model_name, "the robot's model when it is not the program's (a mismatch is refused)");
  addRsiListenOptions(*run, run_options.listen);
  addRsiContextOptions(*run, run_options.context_path, run_options.cycle_ms,
                       "RSI: the RSI context (NAME.rsi.xml) the robot runs, for its correction limits (default: the "
                       "one beside the Ethernet config that names it; rsi-sim: resources/rsi/rci_replay.rsi.xml)");
  addDecimalOption(*run, "--speed", run_options.speed, 0.1, 1.0, "a speed override from 0.1 to 1.0 (e.g. 0.5 = 50 %)",
                   "speed override from 0.1 to 1.0 (default 1.0)")
      ->type_name("R");
  run->add_option("--report", run_options.report_path, "write the run report (JSON) to FILE")
      ->type_name("FILE")
      ->check(CLI::Validator(
          [](std::string& text) { return text.empty() ? std::string("needs a file name") : std::string(); }, ""));
  run->add_flag("--fast", run_options.fast,
                "with --robot sim: the lock-step clock, faster than real time (a controller keeps its own clock)");

  CLI::App* doctor = app.add_subcommand("doctor", "real-time fitness of this machine, with advice");

  CLI::App* bench = app.add_subcommand(
      "bench", "benchmarks: the 1 kHz loop, the client's and the RSI link's cost per cycle, demonstrated paths, a soak "
               "of motions under lost states");
  bench->require_subcommand(1);
  LoopOptions loop_options;
  CLI::App* loop = bench->add_subcommand("loop", "1 kHz joint-position loop: period, jitter, late and lost cycles");
  addRobotOption(*loop, loop_options.robot, true, "sim: an in-process simulator (default); HOST:PORT: a robot");
  addWholeNumberOption(*loop, "--cycles", loop_options.cycles, 1500, 10'000'000, "cycles to run (default 10000)");
  loop->add_flag("--lockstep", loop_options.lockstep, "the in-process simulator on the lock-step clock");
  addModelOption(*loop, loop_options.type, "the model (default xmate7_pro)");
  long client_cycles = 100'000;
  CLI::App* client = bench->add_subcommand("client", "the client's cost per cycle (decode, callback, encode, send)");
  addWholeNumberOption(*client, "--cycles", client_cycles, 1000, 100'000'000, "cycles to measure (default 100000)");
  long rsi_cycles = 100'000;
  CLI::App* rsi_bench = bench->add_subcommand(
      "rsi", "the RSI link's cost per cycle (parse <Rob>, callback, compose <Sen>, send) against a tinyxml2 DOM "
             "and a raw sendto");
  addWholeNumberOption(*rsi_bench, "--cycles", rsi_cycles, 100, 100'000'000, "cycles to measure (default 100000)");
  long path_seconds = 60, path_rounds = 5;
  CLI::App* path_bench = bench->add_subcommand(
      "path", "teach by demonstration: reducing a 1 kHz recording and re-timing it for replay, against writing it "
              "as JSON");
  addWholeNumberOption(*path_bench, "--seconds", path_seconds, 1, 3600, "length of the recording (default 60)");
  addWholeNumberOption(*path_bench, "--rounds", path_rounds, 1, 1000, "rounds to take the median of (default 5)");
  soak::SoakOptions soak_options;
  long soak_seed = soak_options.seed;
  bool soak_json = false;
  CLI::App* soak_bench = bench->add_subcommand(
      "soak", "hundreds of mixed motions (MOVEJ/L/C at full speed, PATH replays, the manual's callbacks) against "
              "the in-process simulator on its real-time clock while it loses states at random and two threads burn "
              "CPU: failures per motion kind, states lost, wall time (exit status 1 when a motion failed)");
  addWholeNumberOption(*soak_bench, "--motions", soak_options.motions, 1, 1'000'000, "motions to run (default 200)");
  addDecimalOption(*soak_bench, "--loss", soak_options.loss_percent, 0, 50, "a percentage from 0 to 50",
                   "states lost at random, % (default 2; 30 % of the losses are pairs, and 5 states in a row are "
                   "lost every 10 s; 0: nothing is lost)")
      ->type_name("PERCENT");
  addWholeNumberOption(*soak_bench, "--seed", soak_seed, 0, 2'147'483'647, "the loss pattern's seed (default 1)");
  soak_bench->add_flag_callback("--no-burners", [&] { soak_options.burners = false; },
                                "no CPU-burning threads beside the soak");
  soak_bench->add_flag("--lockstep", soak_options.lockstep,
                       "the simulator's lock-step clock: states are lost but never late (with --loss 0, a control "
                       "run)");
  soak_bench->add_flag("--json", soak_json, "the figures as JSON");

  FtOptions ft_options;
  CLI::App* ft = app.add_subcommand("ft", "read an ATI Net F/T force/torque sensor: Fx Fy Fz (N) and Tx Ty Tz (Nm) per sample");
  addSensorOption(*ft, ft_options)->required();
  addWholeNumberOption(*ft, "--count", ft_options.count, 1, 100'000'000, "stop after N samples (default: until Ctrl-C)");
  ft->add_option("--counts-per-unit", ft_options.counts_per_unit,
                 "counts per N and per Nm, as the sensor is configured (default 1000000)")
      ->type_name("C")
      ->check(CLI::PositiveNumber);

  GuideOptions guide_options;
  CLI::App* guide = app.add_subcommand(
      "guide", "hand-guide a KUKA over RSI through the force/torque sensor on its flange (docs/guiding.md)");
  addRobotOption(*guide, guide_options.robot, false, "rsi:ETHERNET.xml: the KUKA's RSI Ethernet config", true)
      ->required()
      ->type_name("rsi:FILE");
  addModelNameOption(*guide, guide_options.model_name, "the KUKA arm: kr6_r900_sixx or kr16_2")->required();
  addSensorOption(*guide, guide_options.sensor)->required();
  addRsiListenOptions(*guide, guide_options.listen);
  addRsiContextOptions(*guide, guide_options.context_path, guide_options.cycle_ms,
                       "RSI: the RSI context (NAME.rsi.xml) the robot runs, for its correction limits (default: the "
                       "one beside the Ethernet config that names it)");
  guide->add_option("--axes", guide_options.axes, "what the hand may move: translation (default), rotation or free")
      ->type_name("AXES")
      ->check(CLI::IsMember({"translation", "rotation", "free"}));
  addDecimalOption(*guide, "--tool-mass", guide_options.tool_mass, 0, 50, "a tool mass from 0 to 50 kg",
                   "mass of the tool below the sensor, kg (its weight is removed from every reading; default 0)")
      ->type_name("KG");
  guide->add_option("--tool-center", guide_options.tool_center,
                    "the tool's centre of mass in the flange frame, m (default 0,0,0)")
      ->type_name("X,Y,Z")
      ->delimiter(',')
      ->expected(3);
  addDecimalOption(*guide, "--max-speed", guide_options.max_speed, 0.01, 1.0, "a speed from 0.01 to 1.0 m/s",
                   "the flange's speed cap, m/s (default 0.25)")
      ->type_name("M/S");
  addWholeNumberOption(*guide, "--seconds", guide_options.seconds, 1, 86'400, "stop after S seconds (default: Ctrl-C)")
      ->type_name("S");
  guide->add_option("--counts-per-unit", guide_options.sensor.counts_per_unit,
                    "the sensor's counts per N and per Nm (default 1000000)")
      ->type_name("C")
      ->check(CLI::PositiveNumber);

  CLI::App* help = app.add_subcommand("help", "this text");
  app.set_version_flag("--version", std::string("rci-cli ") + RCI_VERSION, "Print the version and exit");

  try {
    app.parse(argc, argv);
    run_options.rsi_options_given =
        run->count("--bind") + run->count("--port") + run->count("--context") + run->count("--cycle-ms") > 0;
    if (state->parsed()) {
      state_options.bind_given = state->count("--bind") > 0;
      state_options.port_given = state->count("--port") > 0;
      state_options.wait_given = state->count("--wait") > 0;
      checkStateOptions(state_options);
    }
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return 0;
  } catch (const CLI::CallForVersion&) {
    std::printf("rci-cli %s\n", RCI_VERSION);
    return 0;
  } catch (const CLI::ParseError& e) {
    const CLI::App* command = selectedCommand(app);
    return usageError(explain(e, app, command), command);
  } catch (const UsageError& e) {  // thrown by an option's callback
    const CLI::App* command = selectedCommand(app);
    return usageError(e.what(), command);
  }

  try {
    if (help->parsed()) {  // the whole program's help (app.help() would describe `help` itself)
      std::fputs(app.get_formatter()->make_help(&app, app.get_name(), CLI::AppFormatMode::Normal).c_str(), stdout);
      return 0;
    }
    // Commands that talk to a controller pin the whole process in RAM (the library locks only its
    // real-time thread's memory); refused without privileges, reported by the session then.
    if (state->parsed() || run->parsed() || guide->parsed() || loop->parsed() || client->parsed() ||
        rsi_bench->parsed() || soak_bench->parsed())
      xmate::net::lockAllMemory();
    if (state->parsed()) return state_options.robot.rsi ? runStateRsi(state_options) : runState(state_options);
    if (run->parsed()) return runRun(run_options);
    if (guide->parsed()) {
      if (!guide_options.robot.rsi || guide_options.robot.rsi_config.empty())
        throw UsageError("--robot: guide takes rsi:ETHERNET.xml, the KUKA's Ethernet config");
      return runGuide(guide_options);
    }
    if (doctor->parsed()) return runDoctor();
    if (ft->parsed()) return runFt(ft_options);
    if (loop->parsed()) return runBenchLoop(loop_options);
    if (client->parsed()) return runBenchClient(client_cycles);
    if (rsi_bench->parsed()) return runBenchRsi(rsi_cycles);
    if (path_bench->parsed()) return runBenchPath(double(path_seconds), int(path_rounds));
    if (soak_bench->parsed()) return runBenchSoak(soakOptions(soak_options, soak_seed), soak_json);
    return runModel(model_type);  // `rci-cli` alone or `rci-cli model [NAME]`
  } catch (const UsageError& e) {
    const CLI::App* command = selectedCommand(app);
    return usageError(e.what(), command);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rci-cli: %s\n", e.what());
    return 1;
  }
}
