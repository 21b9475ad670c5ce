// SPDX-License-Identifier: Apache-2.0
// The simulated KRC (sim::Krc, sim::KrcServer): the signal flow follows the wiring; unsupported
// objects and wiring cycles are refused with file:line; clamps, HOLDON, Delay, Timeout and restart,
// monitors, #ABSOLUTE vs #RELATIVE, gear torques, DIGIN/DIGOUT, faults; and rsi::Link <-> KrcServer
// end to end on loopback in lock-step. The KRC is stepped by the test: no wall-clock assertions.
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "../planning/allocation_counter.h"
#include "model/robot_spec.h"
#include "net/udp_socket.h"
#include "rsi/codec.h"
#include "rsi/link.h"
#include "rsi_test_support.h"
#include "sim/ft_sensor.h"
#include "sim/krc.h"
#include "sim/krc_control.h"
#include "sim/krc_server.h"

using namespace xmate;
using namespace xmate::sim;
using xmate::rsi::testing::dataPath;
using xmate::rsi::testing::loopback;

namespace {

// The arm every test drives (KR 6 R900 sixx; the KR 16-2 runs the same code).
std::string testModel() { return "kr6_r900_sixx"; }

// An Ethernet config with every kind of channel the tests use.
const char* const kEthernet = R"(<ROOT>
  <CONFIG><IP_NUMBER>127.0.0.1</IP_NUMBER><PORT>49152</PORT><SENTYPE>ImFree</SENTYPE><ONLYSEND>FALSE</ONLYSEND></CONFIG>
  <SEND><ELEMENTS>
    <ELEMENT TAG="DEF_RIst" TYPE="DOUBLE" INDX="INTERNAL" />
    <ELEMENT TAG="DEF_AIPos" TYPE="DOUBLE" INDX="INTERNAL" />
    <ELEMENT TAG="DEF_ASPos" TYPE="DOUBLE" INDX="INTERNAL" />
    <ELEMENT TAG="DEF_MACur" TYPE="DOUBLE" INDX="INTERNAL" />
    <ELEMENT TAG="DEF_Delay" TYPE="LONG" INDX="INTERNAL" />
    <ELEMENT TAG="Out.o1" TYPE="DOUBLE" INDX="1" />
    <ELEMENT TAG="Out.o2" TYPE="DOUBLE" INDX="2" />
    <ELEMENT TAG="Out.o3" TYPE="DOUBLE" INDX="3" />
    <ELEMENT TAG="Out.o4" TYPE="DOUBLE" INDX="4" />
    <ELEMENT TAG="Out.o5" TYPE="DOUBLE" INDX="5" />
    <ELEMENT TAG="Out.o6" TYPE="DOUBLE" INDX="6" />
    <ELEMENT TAG="Status" TYPE="LONG" INDX="7" />
    <ELEMENT TAG="DEF_Tech.C1" TYPE="DOUBLE" INDX="INTERNAL" />
  </ELEMENTS></SEND>
  <RECEIVE><ELEMENTS>
    <ELEMENT TAG="DEF_EStr" TYPE="STRING" INDX="INTERNAL" />
    <ELEMENT TAG="AK.A1" TYPE="DOUBLE" INDX="1" HOLDON="1" />
    <ELEMENT TAG="AK.A2" TYPE="DOUBLE" INDX="2" HOLDON="1" />
    <ELEMENT TAG="AK.A3" TYPE="DOUBLE" INDX="3" HOLDON="1" />
    <ELEMENT TAG="AK.A4" TYPE="DOUBLE" INDX="4" HOLDON="1" />
    <ELEMENT TAG="AK.A5" TYPE="DOUBLE" INDX="5" HOLDON="1" />
    <ELEMENT TAG="AK.A6" TYPE="DOUBLE" INDX="6" HOLDON="1" />
    <ELEMENT TAG="RK.X" TYPE="DOUBLE" INDX="7" HOLDON="0" />
    <ELEMENT TAG="RK.Y" TYPE="DOUBLE" INDX="8" HOLDON="0" />
    <ELEMENT TAG="RK.Z" TYPE="DOUBLE" INDX="9" HOLDON="0" />
    <ELEMENT TAG="RK.A" TYPE="DOUBLE" INDX="10" HOLDON="0" />
    <ELEMENT TAG="RK.B" TYPE="DOUBLE" INDX="11" HOLDON="0" />
    <ELEMENT TAG="RK.C" TYPE="DOUBLE" INDX="12" HOLDON="0" />
    <ELEMENT TAG="Dig.d1" TYPE="BOOL" INDX="13" HOLDON="0" />
    <ELEMENT TAG="Dig.d2" TYPE="BOOL" INDX="14" HOLDON="1" />
    <ELEMENT TAG="DEF_Tech.T2" TYPE="DOUBLE" INDX="INTERNAL" />
  </ELEMENTS></RECEIVE>
</ROOT>
)";

struct Wire {
  int in;
  std::string from;
  int out;
};
struct Param {
  std::string name, value;
};

std::string object(const std::string& type, const std::string& id, const std::vector<Wire>& wires,
                   const std::vector<Param>& params = {}) {
  std::string s = "  <RSIObject ObjType=\"" + type + "\" ObjID=\"" + id + "\">\n    <Inputs>\n";
  for (const Wire& w : wires)
    s += "      <Input InIdx=\"" + std::to_string(w.in) + "\" OutObjID=\"" + w.from + "\" OutIdx=\"" +
         std::to_string(w.out) + "\" />\n";
  s += "    </Inputs>\n    <Parameters>\n";
  for (const Param& p : params)
    s += "      <Parameter Name=\"" + p.name + "\" ParamID=\"1\" ParamValue=\"" + p.value + "\" />\n";
  return s + "    </Parameters>\n  </RSIObject>\n";
}

// ETHERNET1 with inputs wired from `wires` (e.g. GEARTORQUE1 -> inputs 1..6).
std::string ethernet(const std::vector<Wire>& wires, int timeout = 100) {
  return object("ETHERNET", "ETHERNET1", wires,
                {{"ConfigFile", "eth.xml"}, {"Timeout", std::to_string(timeout)}, {"Flag", "1"}, {"Precision", "4"}});
}

// Inputs 1..count of an object from outputs first..first+count-1 of `from`.
std::vector<Wire> range(const std::string& from, int first, int count, int first_in = 1) {
  std::vector<Wire> w;
  for (int k = 0; k < count; ++k) w.push_back({first_in + k, from, first + k});
  return w;
}

// Writes ctx.rsi.xml (the objects) and eth.xml into dir; returns the context's path.
std::string writeContext(const QTemporaryDir& dir, const std::string& objects) {
  const std::string path = dir.path().toStdString() + "/ctx.rsi.xml";
  std::ofstream(path) << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<RSIObjects>\n" << objects << "</RSIObjects>\n";
  std::ofstream(dir.path().toStdString() + "/eth.xml") << kEthernet;
  return path;
}

// The robot side driven by the test, and a PC that answers with SenEncoder (the PC's codec).
class Harness {
 public:
  explicit Harness(KrcConfig c) {
    c.log = [this](const std::string& line) { log.push_back(line); };
    krc = std::make_unique<Krc>(c);
    rob = std::make_unique<rsi::RobDecoder>(krc->ethernetConfig());
    sen = std::make_unique<rsi::SenEncoder>(krc->ethernetConfig());
  }
  Harness(const Harness&) = delete;

  void set(const char* element, const char* attribute, double v) { sen->set(sen->slot(element, attribute), v); }
  void setText(const char* element, const std::string& text) { sen->setText(sen->slot(element, ""), text); }

  // One cycle; the PC answers unless `answer` is false. Returns whether the KRC took an answer.
  bool cycle(bool answer = true) {
    char out[rsi::kMaxDatagramBytes];
    const size_t n = krc->beginCycle(out, sizeof out);
    last_rob.assign(out, n);
    bool took = false;
    if (n > 0) {
      if (!rob->decode(last_rob)) qWarning("the <Rob> did not decode: %s", rob->reason());
      if (answer) {
        char s[rsi::kMaxSenBytes];
        const size_t m = sen->encode(rob->ipocText(), s, sizeof s);
        took = krc->onAnswer({s, m});
      }
    }
    krc->endCycle();
    return took;
  }
  void cycles(int count, bool answer = true) {
    for (int i = 0; i < count; ++i) cycle(answer);
  }
  double robValue(const char* element, const char* attribute) const { return rob->value(rob->slot(element, attribute)); }
  bool logged(const std::string& part) const {
    for (const std::string& l : log)
      if (l.find(part) != std::string::npos) return true;
    return false;
  }
  int loggedCount(const std::string& part) const {
    int n = 0;
    for (const std::string& l : log) n += l.find(part) != std::string::npos;
    return n;
  }

  std::vector<std::string> log;
  std::unique_ptr<Krc> krc;
  std::unique_ptr<rsi::RobDecoder> rob;
  std::unique_ptr<rsi::SenEncoder> sen;
  std::string last_rob;
};

KrcConfig configFor(const std::string& context_path) {
  KrcConfig c;
  c.context_path = context_path;
  c.restart_pause_ms = 40;  // ten cycles
  return c;
}

// The axis-correction context: ETHERNET outputs 1..6 -> AXISCORR1 -> AXISCORRMON1; GEARTORQUE1 and
// STATUS1 to the ETHERNET inputs.
std::string axisContext(const QTemporaryDir& dir, double limit = 5, double monitor = 100, int timeout = 100) {
  std::vector<Param> lim, mon;
  for (int k = 1; k <= 6; ++k) {
    lim.push_back({"LowerLimA" + std::to_string(k), std::to_string(-limit)});
    lim.push_back({"UpperLimA" + std::to_string(k), std::to_string(limit)});
    mon.push_back({"MaxA" + std::to_string(k), std::to_string(monitor)});
  }
  std::vector<Wire> eth_in = range("GEARTORQUE1", 1, 6);
  eth_in.push_back({7, "STATUS1", 1});
  return writeContext(dir, object("GEARTORQUE", "GEARTORQUE1", {}) + object("STATUS", "STATUS1", {}) +
                               ethernet(eth_in, timeout) + object("AXISCORR", "AXISCORR1", range("ETHERNET1", 1, 6), lim) +
                               object("AXISCORRMON", "AXISCORRMON1", range("AXISCORR1", 1, 6), mon));
}

}  // namespace

class TestSimKrc : public QObject {
  Q_OBJECT

 private slots:
  void sampleContextRunsAndSendsItsElements() {
    KrcConfig c;
    c.context_path = dataPath("resources/rsi/rci_axis_corr.rsi.xml");
    Harness h(c);
    QCOMPARE(QString::fromStdString(h.krc->evaluationOrder()),
             QString("ETHERNET1 GEARTORQUE1 STATUS1 OV_PRO1 AXISCORR1 AXISCORRMON1"));
    h.cycles(3);
    QVERIFY(h.last_rob.rfind("<Rob Type=\"ImFree\">", 0) == 0);
    QVERIFY(h.last_rob.find("<IPOC>8</IPOC></Rob>") != std::string::npos);  // 0, 4, 8: IPOC advances by the cycle
    QCOMPARE(h.robValue("AIPos", "A2"), -90.0);
    // DEF_RIst: the flange of the KR 6 R900 sixx at (0, -90, 90, 0, 90, 0) is at (445, 0, 810) mm, A B C (180, 0, 180).
    QVERIFY(std::abs(h.robValue("RIst", "X") - 445) < 1e-3 && std::abs(h.robValue("RIst", "Y")) < 1e-3 &&
            std::abs(h.robValue("RIst", "Z") - 810) < 1e-3);
    QVERIFY(std::abs(std::abs(h.robValue("RIst", "A")) - 180) < 1e-3 && std::abs(h.robValue("RIst", "B")) < 1e-3 &&
            std::abs(std::abs(h.robValue("RIst", "C")) - 180) < 1e-3);
    QCOMPARE(h.robValue("Status", ""), 1.0);     // STATUS: RSI running
    QCOMPARE(h.robValue("Override", ""), 100.0); // OV_PRO
    h.krc->setOverride(30);
    h.cycles(2);
    QCOMPARE(h.robValue("Override", ""), 30.0);
    QCOMPARE(h.krc->status().answers_used, uint64_t(5));
    QCOMPARE(h.krc->status().delay, uint64_t(0));
  }

  void samplePosCorrContextMovesTheFlange() {
    KrcConfig c;
    c.context_path = dataPath("resources/rsi/rci_pos_corr.rsi.xml");
    Harness h(c);
    QCOMPARE(QString::fromStdString(h.krc->evaluationOrder()),
             QString("ETHERNET1 DIGIN1 STATUS1 POSCORR1 POSCORRMON1 DIGOUT1"));
    const KrcStatus before = h.krc->status();
    h.set("RK", "X", 4);
    h.set("RK", "Z", -3);
    h.set("RK", "A", 2);
    h.set("Digout", "O1", 1);
    h.krc->setDigitalInput(2, true);
    h.cycles(300);
    const KrcStatus s = h.krc->status();
    QVERIFY(std::abs(s.pose[0] - (before.pose[0] + 4)) < 1e-3);
    QVERIFY(std::abs(s.pose[1] - before.pose[1]) < 1e-3);
    QVERIFY(std::abs(s.pose[2] - (before.pose[2] - 3)) < 1e-3);
    // Base frame: the flange turned 2 deg about the base z axis (A), B and C kept.
    const double a = std::remainder(s.pose[3] - before.pose[3], 360.0);
    QVERIFY2(std::abs(a - 2) < 1e-3, qPrintable(QString::number(a)));
    QCOMPARE(s.digout, uint64_t(1));
    QCOMPARE(h.robValue("Digin", "I2"), 1.0);
    QCOMPARE(h.robValue("Status", ""), 1.0);
    QCOMPARE(s.state, KrcState::kRunning);
  }

  void inputsFollowTheWiring() {
    // ETHERNET output 3 (AK.A3) feeds AXISCORR input 1 (A1); AXISCORR's output 1 goes back to ETHERNET input 2.
    QTemporaryDir dir;
    const std::string ctx = writeContext(dir, ethernet({{2, "AXISCORR1", 1}}) +
                                                  object("AXISCORR", "AXISCORR1", {{1, "ETHERNET1", 3}}));
    Harness h(configFor(ctx));
    h.set("AK", "A3", 2.0);
    h.set("AK", "A1", -4.0);  // output 1 is wired to nothing
    h.cycles(100);
    const KrcStatus s = h.krc->status();
    QCOMPARE(s.axis_corr_deg[0], 2.0);
    QCOMPARE(s.axis_corr_deg[2], 0.0);
    QVERIFY(std::abs(s.q_deg[0] - (s.start_deg[0] + 2)) < 1e-6);
    QCOMPARE(h.krc->output("AXISCORR1", 1), 2.0);
    h.cycle();
    QCOMPARE(h.robValue("Out", "o2"), 2.0);  // the loop through ETHERNET, one cycle later
    QCOMPARE(h.robValue("Out", "o1"), 0.0);  // an input nobody wired is sent as 0
  }

  void unsupportedObjectIsRefusedWithFileAndLine() {
    QTemporaryDir dir;
    const std::string ctx = writeContext(dir, ethernet({}) + object("PT1", "FILTER1", {{1, "ETHERNET1", 1}}));
    try {
      KrcConfig c = configFor(ctx);
      c.model = testModel();
      Krc krc(c);
      QFAIL("accepted");
    } catch (const KrcError& e) {
      const QString what = e.what();
      // The PT1 object starts on line 12 (declaration, root, 9 lines of ETHERNET1 plus its parameters).
      QVERIFY2(what.startsWith(QString::fromStdString(ctx) + ":"), qPrintable(what));
      QVERIFY2(what.contains("FILTER1 (PT1)") && what.contains("not supported") && what.contains("AXISCORR"),
               qPrintable(what));
      const int line = what.section(':', 1, 1).toInt();
      std::ifstream in(ctx);
      std::string text;
      for (int i = 0; i < line; ++i) std::getline(in, text);
      QVERIFY2(text.find("ObjID=\"FILTER1\"") != std::string::npos, text.c_str());
    }
  }

  void wiringCycleIsRefused() {
    QTemporaryDir dir;
    const std::string ctx = writeContext(dir, ethernet({}) + object("DIGOUT", "DIGOUT1", {{1, "DIGOUT2", 1}}) +
                                                  object("DIGOUT", "DIGOUT2", {{1, "DIGOUT1", 1}}));
    try {
      KrcConfig c = configFor(ctx);
      c.model = testModel();
      Krc krc(c);
      QFAIL("accepted");
    } catch (const KrcError& e) {
      const QString what = e.what();
      QVERIFY2(what.contains("wiring cycle") && what.contains("DIGOUT1 -> DIGOUT2 -> DIGOUT1"), qPrintable(what));
      QVERIFY2(what.startsWith(QString::fromStdString(ctx) + ":"), qPrintable(what));
    }
    // A wire to an output the source does not have.
    const std::string bad = writeContext(dir, ethernet({}) + object("AXISCORR", "AXISCORR1", {{1, "ETHERNET1", 65}}));
    KrcConfig c = configFor(bad);
    c.model = testModel();
    QVERIFY_THROWS_EXCEPTION(KrcError, Krc{c});
  }

  void axisCorrectionIsClampedAndSaidOnce() {
    QTemporaryDir dir;
    Harness h(configFor(axisContext(dir, 5)));
    h.set("AK", "A1", 7.0);
    h.set("AK", "A2", -1.5);
    h.cycles(200);
    const KrcStatus s = h.krc->status();
    QCOMPARE(s.axis_corr_deg[0], 5.0);
    QCOMPARE(s.axis_corr_deg[1], -1.5);
    QVERIFY(std::abs(s.q_deg[0] - (s.start_deg[0] + 5)) < 1e-6);
    QVERIFY(std::abs(s.q_deg[1] - (s.start_deg[1] - 1.5)) < 1e-6);
    QCOMPARE(h.loggedCount("AXISCORR1: the correction of A1 (7.000 deg) reached UpperLimA1 = 5.000"), 1);
    QCOMPARE(h.robValue("Status", ""), 1.0);
    QCOMPARE(s.status_bits & 1, 1);  // STATUS output 2, bit 0: an axis correction is held at its limit
  }

  void cartesianCorrectionIsClampedAndReached() {
    QTemporaryDir dir;
    const std::string ctx = writeContext(
        dir, ethernet({}) + object("POSCORR", "POSCORR1", range("ETHERNET1", 7, 6),
                                   {{"LowerLimX", "-5"}, {"UpperLimX", "5"}, {"LowerLimZ", "-2"}, {"UpperLimZ", "2"},
                                    {"MaxRotAngle", "1"}, {"RefCorrSys", "Base"}}));
    Harness h(configFor(ctx));
    const KrcStatus before = h.krc->status();
    h.set("RK", "X", 3.0);
    h.set("RK", "Z", -4.0);
    h.set("RK", "C", 2.0);
    h.cycles(300);
    const KrcStatus s = h.krc->status();
    QCOMPARE(s.pos_corr[0], 3.0);
    QCOMPARE(s.pos_corr[2], -2.0);
    QCOMPARE(s.pos_corr[5], 1.0);
    QVERIFY(h.logged("POSCORR1: the correction of Z (-4.000 mm) reached LowerLimZ = -2.000"));
    QVERIFY(h.logged("POSCORR1: the correction of C (2.000 deg) reached MaxRotAngle = 1.000"));
    QVERIFY2(std::abs(s.pose[0] - (before.pose[0] + 3)) < 1e-3, qPrintable(QString::number(s.pose[0] - before.pose[0])));
    QVERIFY(std::abs(s.pose[1] - before.pose[1]) < 1e-3);
    QVERIFY(std::abs(s.pose[2] - (before.pose[2] - 2)) < 1e-3);
  }

  void lateAnswersHoldOnOrFallToZeroAndCountDelay() {
    QTemporaryDir dir;
    const std::string ctx = writeContext(dir, ethernet({}) + object("DIGOUT", "DIGOUT1", range("ETHERNET1", 13, 2)));
    Harness h(configFor(ctx));
    h.set("Dig", "d1", 1);
    h.set("Dig", "d2", 1);
    h.cycles(2);
    QCOMPARE(h.krc->status().digout, uint64_t(3));
    h.cycle(false);  // late: d1 (HOLDON 0) falls to 0, d2 (HOLDON 1) keeps its value
    QCOMPARE(h.krc->status().digout, uint64_t(2));
    QCOMPARE(h.krc->status().delay, uint64_t(1));
    h.cycle(false);
    h.cycle();
    QCOMPARE(h.robValue("Delay", "D"), 2.0);  // the <Rob> after two late answers says so
    QCOMPARE(h.krc->status().digout, uint64_t(3));
    QCOMPARE(h.krc->status().late_in_a_row, uint64_t(0));
    QCOMPARE(h.krc->status().answers_late, uint64_t(2));
  }

  void timeoutStopsRsiThenANewSessionStarts() {
    QTemporaryDir dir;
    Harness h(configFor(axisContext(dir, 5, 100, 3)));
    h.set("AK", "A1", 2.0);
    h.cycles(50);
    QCOMPARE(h.krc->status().session, 1u);
    h.cycles(3, false);  // three late in a row: tolerated (Timeout 3)
    QCOMPARE(h.krc->status().state, KrcState::kRunning);
    h.cycle(false);  // the fourth
    KrcStatus s = h.krc->status();
    QCOMPARE(s.state, KrcState::kPaused);
    QCOMPARE(s.last_stop, KrcStop::kTimeout);
    QCOMPARE(s.timeouts, uint64_t(1));
    QVERIFY(h.logged("Signal flow (running): Object ETHERNET1 returns error RSITimeout"));
    const double held = s.q_deg[0];
    char out[rsi::kMaxDatagramBytes];
    QCOMPARE(h.krc->beginCycle(out, sizeof out), size_t(0));  // nothing is sent while RSI is off
    h.krc->endCycle();
    h.cycles(9);
    s = h.krc->status();
    QCOMPARE(s.state, KrcState::kRunning);  // after the pause (40 ms = 10 cycles) RSI_ON again
    QCOMPARE(s.session, 2u);
    QCOMPARE(s.delay, uint64_t(0));
    QCOMPARE(s.start_deg[0], held);  // corrections are relative to the new start pose
    h.cycles(100);
    QVERIFY(std::abs(h.krc->status().q_deg[0] - (held + 2)) < 1e-6);
  }

  void noRestartWhenThePauseIsZero() {
    QTemporaryDir dir;
    KrcConfig c = configFor(axisContext(dir, 5, 100, 0));
    c.restart_pause_ms = 0;
    Harness h(c);
    h.cycle(false);
    QCOMPARE(h.krc->status().state, KrcState::kStopped);
    QCOMPARE(h.krc->status().program_status, 2);
    h.cycles(100);
    QCOMPARE(h.krc->status().session, 1u);
    QVERIFY(h.logged("no restart"));
  }

  void monitorsStopRsi() {
    QTemporaryDir dir;
    Harness h(configFor(axisContext(dir, 10, 3)));
    h.set("AK", "A2", 2.5);
    h.cycles(10);
    QCOMPARE(h.krc->status().state, KrcState::kRunning);
    h.set("AK", "A2", 3.5);
    h.cycle();
    QCOMPARE(h.krc->status().state, KrcState::kPaused);
    QCOMPARE(h.krc->status().last_stop, KrcStop::kAxisMonitor);
    QVERIFY(h.logged("AXISCORRMON1: the total correction of A2 is 3.500 deg, beyond MaxA2 = 3.000 deg"));

    QTemporaryDir dir2;
    const std::string ctx = writeContext(
        dir2, ethernet({}) +
                  object("POSCORR", "POSCORR1", range("ETHERNET1", 7, 6),
                         {{"LowerLimX", "-10"}, {"UpperLimX", "10"}, {"LowerLimY", "-10"}, {"UpperLimY", "10"}}) +
                  object("POSCORRMON", "POSCORRMON1", range("POSCORR1", 1, 6), {{"MaxTrans", "4"}, {"MaxRotAngle", "3"}}));
    Harness p(configFor(ctx));
    p.set("RK", "X", 3);
    p.set("RK", "Y", 3);  // 4.24 mm in all
    p.cycle();
    QCOMPARE(p.krc->status().last_stop, KrcStop::kPosMonitor);
    QVERIFY(p.logged("POSCORRMON1: the total translation of the correction is 4.243 mm, beyond MaxTrans = 4.000 mm"));
  }

  void absoluteHoldsRelativeAdds() {
    QTemporaryDir dir;
    const std::string ctx = axisContext(dir, 5);
    Harness a(configFor(ctx));
    a.set("AK", "A6", 1.0);
    a.cycles(5);
    QCOMPARE(a.krc->status().axis_corr_deg[5], 1.0);  // the same AK every cycle holds still
    KrcConfig rc = configFor(ctx);
    rc.mode = rsi::CorrectionMode::kRelative;
    Harness r(rc);
    r.set("AK", "A6", 1.0);
    r.cycles(3);
    QCOMPARE(r.krc->status().axis_corr_deg[5], 3.0);  // each correction adds to the previous ones
    r.cycles(5);
    QCOMPARE(r.krc->status().axis_corr_deg[5], 5.0);  // up to the limit
    r.set("AK", "A6", 0.0);
    r.cycles(300);
    QCOMPARE(r.krc->status().axis_corr_deg[5], 5.0);  // 0 stays
    QVERIFY(std::abs(r.krc->status().q_deg[5] - (r.krc->status().start_deg[5] + 5)) < 1e-6);
  }

  void motionKeepsTheAxisSpeeds() {
    QTemporaryDir dir;
    Harness h(configFor(axisContext(dir, 30)));
    const model::RobotSpec* spec = model::findRobotSpec(testModel());
    h.set("AK", "A1", 25.0);
    double previous = h.krc->status().q_deg[0];
    int cycles = 0;
    for (; cycles < 2000 && std::abs(h.krc->status().q_deg[0] - (h.krc->status().start_deg[0] + 25)) > 1e-6; ++cycles) {
      h.cycle();
      const double q = h.krc->status().q_deg[0];
      QVERIFY(std::abs(q - previous) / 0.004 <= spec->dq_max[0] * 180 / M_PI * (1 + 1e-9));
      previous = q;
    }
    QVERIFY(cycles < 2000);
    // Never faster than the axis allows: at least 25 deg / v_max.
    QVERIFY(cycles * 0.004 >= 25 / (spec->dq_max[0] * 180 / M_PI));
    QVERIFY(std::abs(h.krc->status().q_set_deg[0] - (h.krc->status().start_deg[0] + 25)) < 1e-9);
  }

  void gearTorquesHoldGravityAndFeelThePush() {
    QTemporaryDir dir;
    Harness h(configFor(axisContext(dir)));
    h.cycles(3);
    const KrcStatus s = h.krc->status();
    // A1 turns about the vertical: gravity gives it nothing; A2 carries the arm: clearly loaded.
    QVERIFY2(std::abs(s.gear_torque[0]) < 1e-6, qPrintable(QString::number(s.gear_torque[0])));
    QVERIFY2(std::abs(s.gear_torque[1]) > 5 && std::abs(s.gear_torque[1]) < 2000, qPrintable(QString::number(s.gear_torque[1])));
    QVERIFY(std::abs(h.robValue("Out", "o2") - s.gear_torque[1]) < 1e-4);  // GEARTORQUE1 -> ETHERNET input 2
    QVERIFY(std::abs(h.robValue("MACur", "A2") - s.gear_torque[1] / 10) < 1e-3);  // 10 Nm per A
    // A sideways push at the flange turns A1's torque.
    h.krc->setExternalWrench({0, 50, 0, 0, 0, 0});
    h.cycles(2);
    QVERIFY(std::abs(h.krc->status().gear_torque[0]) > 1);
    const std::array<double, 6> flange = h.krc->flangeWrench();
    QVERIFY(std::abs(std::hypot(flange[0], flange[1], flange[2]) - 50) < 1e-9);
  }

  void digitalInputsAndOutputs() {
    QTemporaryDir dir;
    const std::string ctx = writeContext(dir, object("DIGIN", "DIGIN1", {}, {{"Index", "3"}}) +
                                                  ethernet(range("DIGIN1", 1, 2, 5)) +
                                                  object("DIGOUT", "DIGOUT1", range("ETHERNET1", 13, 2), {{"Index", "9"}}));
    Harness h(configFor(ctx));
    h.krc->setDigitalInput(4, true);  // DIGIN1 output 2 (Index 3: inputs 3, 4, ...)
    h.cycles(2);
    QCOMPARE(h.robValue("Out", "o5"), 0.0);
    QCOMPARE(h.robValue("Out", "o6"), 1.0);
    h.set("Dig", "d2", 1);
    h.cycle();
    QCOMPARE(h.krc->status().digout, uint64_t(1) << 9);  // output 10
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, h.krc->setDigitalInput(65, true));
  }

  void faultsDropDelayDuplicateSuspend() {
    QTemporaryDir dir;
    Harness h(configFor(axisContext(dir)));
    h.krc->dropAnswers(2);
    h.cycles(3);
    QCOMPARE(h.krc->status().answers_dropped, uint64_t(2));
    QCOMPARE(h.krc->status().delay, uint64_t(2));
    h.krc->delayAnswers(1);
    h.cycle();
    QCOMPARE(h.krc->status().answers_delayed, uint64_t(1));
    QCOMPARE(h.krc->status().delay, uint64_t(3));
    // A duplicate <Rob> is answered twice: the second answer is stale.
    h.krc->duplicateRobs(1);
    char out[rsi::kMaxDatagramBytes];
    const size_t n = h.krc->beginCycle(out, sizeof out);
    QVERIFY(h.krc->takeDuplicate());
    QVERIFY(!h.krc->takeDuplicate());
    QVERIFY(h.rob->decode({out, n}));
    char s[rsi::kMaxSenBytes];
    const size_t m = h.sen->encode(h.rob->ipocText(), s, sizeof s);
    QVERIFY(h.krc->onAnswer({s, m}));
    QVERIFY(!h.krc->onAnswer({s, m}));
    h.krc->endCycle();
    QCOMPARE(h.krc->status().answers_stale, uint64_t(1));
    QCOMPARE(h.krc->status().delay, uint64_t(3));
    // An unreadable answer is refused with the decoder's reason.
    h.krc->beginCycle(out, sizeof out);
    QVERIFY(!h.krc->onAnswer("<Rob><IPOC>1</IPOC></Rob>"));
    QCOMPARE(QString(h.krc->lastReason()), QString("not a <Sen> datagram"));
    h.krc->endCycle();
    // Sending stops without a timeout, and RSI comes back as a new session.
    h.krc->suspendSending(20);
    h.cycle();
    QCOMPARE(h.krc->status().state, KrcState::kSuspended);
    QCOMPARE(h.krc->status().timeouts, uint64_t(0));
    h.cycles(5);
    QCOMPARE(h.krc->status().state, KrcState::kRunning);
    QCOMPARE(h.krc->status().session, 2u);
  }

  // The control port's lines (rci-sim --rsi --control-port) reach the same scene and faults.
  void controlLinesDriveTheSceneAndFaults() {
    QTemporaryDir dir;
    Harness h(configFor(axisContext(dir)));
    Krc& k = *h.krc;
    QCOMPARE(QString::fromStdString(executeKrcControlLine(k, "wrench 0 0 -20 0 0 0")),
             QString("ok wrench 0 0 -20 N, 0 0 0 Nm (base frame, at the flange)"));
    h.cycle();
    QCOMPARE(k.flangeWrench()[2] * k.flangeWrench()[2] + k.flangeWrench()[0] * k.flangeWrench()[0] +
                 k.flangeWrench()[1] * k.flangeWrench()[1],
             400.0);
    QCOMPARE(QString::fromStdString(executeKrcControlLine(k, "di 3 1")), QString("ok di 3 = 1"));
    QCOMPARE(QString::fromStdString(executeKrcControlLine(k, "override 50")), QString("ok override 50 %"));
    h.cycle();
    QCOMPARE(k.status().digin, uint64_t(1) << 2);
    QCOMPARE(k.status().override_pct, 50.0);
    QVERIFY(executeKrcControlLine(k, "drop answers 2").rfind("ok dropping the next 2 answers", 0) == 0);
    h.cycles(3);
    QCOMPARE(k.status().answers_dropped, uint64_t(2));
    QVERIFY(executeKrcControlLine(k, "suspend 20").rfind("ok RSI off for 20 ms", 0) == 0);
    h.cycle();
    QCOMPARE(k.status().state, KrcState::kSuspended);
    const std::string status = executeKrcControlLine(k, "status");
    QVERIFY2(status.rfind("ok state=suspended", 0) == 0 && status.find(" answers_dropped=2 ") != std::string::npos,
             status.c_str());
    // Mistakes say what was wrong and how to write it.
    QCOMPARE(QString::fromStdString(executeKrcControlLine(k, "di 65 1")),
             QString("error di: the input index must be a whole number from 1 to 64, got '65'; usage: di INDEX(1-64) "
                     "LEVEL(0|1)"));
    QVERIFY(executeKrcControlLine(k, "drop states 2").rfind("error drop: this fault applies to answers only, got 'states'", 0) == 0);
    QVERIFY(executeKrcControlLine(k, "estop on").rfind("error unknown command 'estop'; type help", 0) == 0);
    QVERIFY(executeKrcControlLine(k, "help").find("wrench FX FY FZ TX TY TZ") != std::string::npos);
  }

  void smartPadMessageAndTechnologyValues() {
    QTemporaryDir dir;
    Harness h(configFor(axisContext(dir)));
    h.setText("EStr", "hello from the PC");
    h.set("Tech", "T23", 7.5);
    h.cycles(5);
    QCOMPARE(h.loggedCount("smartPAD message from the PC (DEF_EStr): hello from the PC"), 1);
    QCOMPARE(h.krc->status().tech_t2[2], 7.5);  // DEF_Tech.T2: T21..T210
    QVERIFY(h.last_rob.find("<Tech C11=\"0.0000\"") != std::string::npos);  // DEF_Tech.C1: ten values, 0
    QCOMPARE(h.robValue("Tech", "C110"), 0.0);
  }

  void kr16RunsTheSameContext() {
    KrcConfig c;
    c.context_path = dataPath("resources/rsi/rci_axis_corr.rsi.xml");
    c.model = "kr16_2";
    c.cycle_ms = 12;
    Krc krc(c);
    const KrcStatus s = krc.status();
    // The KR 16-2's flange at (0, -90, 90, 0, 90, 0): (930, 0, 1162) mm.
    QVERIFY2(std::abs(s.pose[0] - 930) < 1e-3 && std::abs(s.pose[1]) < 1e-3 && std::abs(s.pose[2] - 1162) < 1e-3,
             qPrintable(QString("%1 %2 %3").arg(s.pose[0]).arg(s.pose[1]).arg(s.pose[2])));
    KrcConfig x = c;
    x.model = "xmate7_pro";
    try {
      Krc seven(x);
      QFAIL("a 7-axis arm was accepted");
    } catch (const KrcError& e) {
      QVERIFY2(QString(e.what()).contains("has 7 axes"), e.what());
    }
  }

  void aCycleAllocatesNothing() {
    QTemporaryDir dir;
    const std::string ctx = writeContext(
        dir, object("GEARTORQUE", "GEARTORQUE1", {}) + object("DIGIN", "DIGIN1", {}) +
                 ethernet(range("GEARTORQUE1", 1, 6)) + object("AXISCORR", "AXISCORR1", range("ETHERNET1", 1, 6)) +
                 object("POSCORR", "POSCORR1", range("ETHERNET1", 7, 6)) +
                 object("DIGOUT", "DIGOUT1", range("ETHERNET1", 13, 2)));
    Harness h(configFor(ctx));
    char out[rsi::kMaxDatagramBytes];
    char answer[rsi::kMaxSenBytes];
    const auto cycle = [&](int i) {
      const size_t n = h.krc->beginCycle(out, sizeof out);
      h.rob->decode({out, n});
      h.sen->set(h.sen->slot("AK", "A1"), 0.001 * (i % 100));   // moving, never clamped
      h.sen->set(h.sen->slot("RK", "Z"), 0.002 * (i % 50));     // a new IK solution most cycles
      h.sen->set(h.sen->slot("Dig", "d1"), i % 2);
      const size_t m = h.sen->encode(h.rob->ipocText(), answer, sizeof answer);
      if (i % 10 != 3) h.krc->onAnswer({answer, m});             // one in ten late
      h.krc->endCycle();
    };
    for (int i = 0; i < 20; ++i) cycle(i);
    const size_t log_lines = h.log.size();
    const std::size_t before = planning_test::allocationCount();
    for (int i = 20; i < 2020; ++i) cycle(i);
    QCOMPARE(planning_test::allocationCount() - before, std::size_t(0));
    QCOMPARE(h.log.size(), log_lines);  // no event: nothing to say
    QVERIFY(h.krc->status().answers_late >= 200);
  }

  void linkDrivesTheKrcInLockStep() {
    rsi::EthernetConfig eth = rsi::readEthernetConfig(dataPath("resources/rsi/RSI_EthernetConfig.xml"));
    const int a1_slot = rsi::RobDecoder(eth).slot("AIPos", "A1");
    std::atomic<double> seen_a1{NAN};
    rsi::LinkOptions lo = loopback();  // a free port of its own
    lo.silence_ms = 5000;
    auto link_holder = std::make_unique<rsi::Link>(eth, lo);
    link_holder->setCallback([&](const rsi::RobDecoder& rob) {
      seen_a1.store(rob.value(a1_slot));
      rsi::Correction c;
      c.kind = rsi::Correction::Kind::kAxis;
      c.values = {3, 0, -2, 0, 0, 0};  // the total since RSI_ON, degrees
      return c;
    });
    link_holder->start();
    rsi::Link& link = *link_holder;

    SimulatedFtSensor sensor(FtSensorConfig{"127.0.0.1", 0});
    KrcServerConfig sc;
    sc.krc.context_path = dataPath("resources/rsi/rci_axis_corr.rsi.xml");
    sc.krc.model = testModel();
    sc.target_ip = "127.0.0.1";
    sc.target_port = link.port();
    sc.lockstep_timeout_ms = 5000;
    sc.ft_sensor = &sensor;
    KrcServer krc(sc);
    krc.krc().setExternalWrench({0, 0, -20, 0, 0, 0});
    const model::RobotSpec* spec = model::findRobotSpec(testModel());
    double previous = krc.krc().status().q_deg[0];
    for (int i = 0; i < 400; ++i) {
      QVERIFY(krc.step());
      const double q = krc.krc().status().q_deg[0];
      QVERIFY(std::abs(q - previous) <= spec->dq_max[0] * 180 / M_PI * 0.004 * (1 + 1e-9));
      previous = q;
    }
    const KrcStatus s = krc.krc().status();
    QVERIFY(std::abs(s.q_deg[0] - (s.start_deg[0] + 3)) < 1e-6);
    QVERIFY(std::abs(s.q_deg[2] - (s.start_deg[2] - 2)) < 1e-6);
    QCOMPARE(s.answers_used, uint64_t(400));
    QCOMPARE(s.delay, uint64_t(0));
    QVERIFY(std::abs(seen_a1.load() - s.q_deg[0]) < 0.01);  // the link read the KRC's DEF_AIPos (one cycle earlier)
    QTRY_COMPARE(link.counters().received, uint64_t(400));
    link.stop();
  }
};

QTEST_GUILESS_MAIN(TestSimKrc)
#include "test_sim_krc.moc"
