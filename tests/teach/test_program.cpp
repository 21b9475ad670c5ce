// SPDX-License-Identifier: Apache-2.0
// The program file format: the JSON text layer on nlohmann-json (escapes, numbers, line:column
// errors, duplicate members, overflow, invalid UTF-8, the saved layout), programs round-tripping
// through files, every kind of bad field named by instruction and field, atomic saving that never
// loses the previous file, and truncated or garbled inputs that never crash.
#include <QtTest>

#include <cmath>
#include <random>

#include "teach/atomic_file.h"
#include "teach/json_text.h"
#include "teach/program_io.h"
#include "teach/recording.h"

using namespace xmate;
using namespace xmate::teach;

namespace {

const std::array<double, 16> kPose{1, 0, 0, 0.5, 0, -1, 0, 0.1, 0, 0, -1, 0.4, 0, 0, 0, 1};

Program sampleProgram() {
  Program p;
  p.robot = &xmate::model::robotSpec(XMATE7_PRO);
  Target q;
  q.has_q = true;
  q.q = {0.1, 0.2, 0.3, 1.2, -0.1, 1.1, 0.7};
  Target pose;
  pose.has_pose = true;
  pose.pose = kPose;
  pose.has_psi = true;
  pose.psi = 0.25;
  Target both = q;
  both.has_pose = true;
  both.pose = kPose;
  both.pose[3] = 0.45;
  both.has_psi = true;
  both.psi = -0.5;
  p.instructions.push_back(moveJ(q, 0.3, "P1"));
  p.instructions.push_back(moveL(pose, 0.2));
  p.instructions.push_back(moveC(pose, both, 1.0, "arc \"quoted\" \\ name"));
  Instruction wait;
  wait.type = InstructionType::kWait;
  wait.ms = 500;
  p.instructions.push_back(wait);
  Instruction set;
  set.type = InstructionType::kSetDo;
  set.signal = 1;
  set.value = true;
  p.instructions.push_back(set);
  Instruction waitDi;
  waitDi.type = InstructionType::kWaitDi;
  waitDi.signal = 5;
  waitDi.value = false;
  waitDi.timeout_ms = 2000;
  p.instructions.push_back(waitDi);
  return p;
}

bool sameTarget(const Target& a, const Target& b) {
  return a.has_q == b.has_q && a.q == b.q && a.has_pose == b.has_pose && a.pose == b.pose && a.has_psi == b.has_psi &&
         (!a.has_psi || a.psi == b.psi);
}

bool sameProgram(const Program& a, const Program& b) {
  if (a.robot != b.robot || a.instructions.size() != b.instructions.size()) return false;
  if (a.has_tool != b.has_tool || a.tool != b.tool || a.load.mass != b.load.mass || a.load.center != b.load.center ||
      a.load.inertia != b.load.inertia)
    return false;
  for (size_t i = 0; i < a.instructions.size(); ++i) {
    const Instruction &x = a.instructions[i], &y = b.instructions[i];
    if (x.type != y.type || x.name != y.name) return false;
    if (isMotion(x.type) && (!sameTarget(x.target, y.target) || x.speed != y.speed)) return false;
    if (x.type == InstructionType::kMoveC && !sameTarget(x.via, y.via)) return false;
    if (x.type == InstructionType::kWait && x.ms != y.ms) return false;
    if ((x.type == InstructionType::kSetDo || x.type == InstructionType::kWaitDi) &&
        (x.signal != y.signal || x.value != y.value || x.timeout_ms != y.timeout_ms))
      return false;
  }
  return true;
}

// The message of the ProgramError that parsing `text` throws ("" if it parses).
QString errorOf(const std::string& text) {
  try {
    parseProgram(text);
  } catch (const ProgramError& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

// A one-instruction program with the given instruction JSON.
std::string withInstruction(const std::string& instruction, const std::string& robot = "xmate7_pro") {
  return R"({"format": "rci-program", "version": 1, "robot": ")" + robot + R"(", "instructions": [)" + instruction +
         "]}";
}

const char* kPoseJson = "[1,0,0,0.5, 0,-1,0,0.1, 0,0,-1,0.4, 0,0,0,1]";

std::string dataDir() {
  const QByteArray dir = qgetenv("RCI_DATA_DIR");
  return dir.isEmpty() ? std::string(".") : dir.toStdString();
}

}  // namespace

class TestProgram : public QObject {
  Q_OBJECT

 private slots:
  void jsonParsesEveryKind();
  void jsonEscapesRoundTrip();
  void jsonErrorsSayLineAndColumn_data();
  void jsonErrorsSayLineAndColumn();
  void programJsonErrorsSayWhatAndWhere_data();
  void programJsonErrorsSayWhatAndWhere();
  void savedTextKeepsItsLayout();
  void programRoundTripsThroughAFile();
  void toolAndLoadRoundTrip();
  void exampleProgramLoads();
  void kukaSignalsAreNamedAsOnTheController();
  void badFieldsAreNamed_data();
  void badFieldsAreNamed();
  void robotMismatchIsRefused();
  void atomicSaveReplacesAndLeavesNoTemporary();
  void atomicSaveKeepsPermissionsAndSymlinks();
  void failedSaveKeepsThePreviousFile();
  void truncatedInputsNeverCrash();
  void garbledInputsNeverCrash();
  void recordingFromState();
};

void TestProgram::jsonParsesEveryKind() {
  const Json v = parseJsonText(R"( {"a": [1, -2.5e3, 0.125, 1E-2], "b": true, "c": false, "d": null, "e": "x", "f": {}} )");
  QVERIFY(v.is_object());
  QCOMPARE(v.size(), size_t(6));
  const Json& a = v.at("a");
  QVERIFY(a.is_array() && a.size() == 4);
  QCOMPARE(a[1].get<double>(), -2500.0);
  QCOMPARE(a[3].get<double>(), 0.01);
  QVERIFY(v.at("b").get<bool>());
  QVERIFY(!v.at("c").get<bool>());
  QVERIFY(v.at("d").is_null());
  QCOMPARE(v.at("e").get<std::string>(), std::string("x"));
  QVERIFY(v.at("f").is_object());
  QVERIFY(v.find("missing") == v.end());
  // Member order is kept.
  std::string keys;
  for (const auto& item : v.items()) keys += item.key();
  QCOMPARE(keys, std::string("abcdef"));
  // Doubles round-trip exactly; underflow reads as 0.
  Json n = Json::array();
  for (double d : {0.1, 1.0 / 3.0, -1e-300, 6.02214076e23, 0.0}) n.push_back(d);
  const Json back = parseJsonText(jsonText(n));
  for (size_t i = 0; i < n.size(); ++i) QCOMPARE(back[i].get<double>(), n[i].get<double>());
  QCOMPARE(parseJsonText("[1e-999]")[0].get<double>(), 0.0);
  // Non-finite numbers cannot be written.
  QVERIFY_THROWS_EXCEPTION(std::invalid_argument, jsonText(Json::array({NAN})));
  QVERIFY_THROWS_EXCEPTION(std::invalid_argument, jsonText(Json::array({INFINITY})));
}

void TestProgram::jsonEscapesRoundTrip() {
  const Json v = parseJsonText(R"(["a\"b\\c\/d\b\f\n\r\t", "\u00e9\u20ac", "\ud83d\ude00"])");
  QCOMPARE(v[0].get<std::string>(), std::string("a\"b\\c/d\b\f\n\r\t"));
  QCOMPARE(v[1].get<std::string>(), std::string("\xc3\xa9\xe2\x82\xac"));
  QCOMPARE(v[2].get<std::string>(), std::string("\xf0\x9f\x98\x80"));
  Json s = Json::array();
  s.push_back(std::string("ctl\x01 \"q\" \\ \n \xc3\xa9"));
  QCOMPARE(parseJsonText(jsonText(s))[0].get<std::string>(), s[0].get<std::string>());
  // A string that is not UTF-8 is written with U+FFFD in place of the bad byte, so it reads back.
  Json bad = Json::array({std::string("a\xff")});
  QCOMPARE(parseJsonText(jsonText(bad))[0].get<std::string>(), std::string("a\xef\xbf\xbd"));
}

void TestProgram::jsonErrorsSayLineAndColumn_data() {
  QTest::addColumn<QByteArray>("text");
  QTest::addColumn<QString>("expected");
  QTest::newRow("bad literal") << QByteArray("{\n  \"a\": tru\n}") << "line 2, column 11: syntax error while parsing value - invalid literal";
  QTest::newRow("missing comma") << QByteArray("[1 2]") << "line 1, column 4: syntax error while parsing array - unexpected number literal; expected ']'";
  QTest::newRow("trailing text") << QByteArray("{} x") << "line 1, column 4: syntax error while parsing value - invalid literal; last read: '{} x'; expected end of input";
  QTest::newRow("duplicate key") << QByteArray("{\"a\": 1,\n \"a\": 2}") << "line 2, column 2: duplicate member \"a\"";
  QTest::newRow("duplicate nested key") << QByteArray("[{\"a\": {\"b\": 1, \"a\": 2}, \"b\": 3, \"b\\\"\": 4, \"b\": 5}]")
                                        << "line 1, column 44: duplicate member \"b\"";
  QTest::newRow("NaN") << QByteArray("[NaN]") << "line 1, column 2: syntax error while parsing value - invalid literal; last read: '[N' (NaN and Infinity are not JSON numbers";
  QTest::newRow("Infinity") << QByteArray("[-Infinity]") << "line 1, column 3: syntax error while parsing value - invalid number; expected digit after '-'; last read: '-I' (NaN and Infinity are not JSON numbers";
  QTest::newRow("overflow") << QByteArray("[0,\n 1e999]") << "line 2, column 2: number 1e999 is out of range";
  QTest::newRow("negative overflow") << QByteArray("[-1.5e400, 2]") << "line 1, column 2: number -1.5e400 is out of range";
  QTest::newRow("leading zero") << QByteArray("[01]") << "line 1, column 3: syntax error while parsing array - unexpected number literal";
  QTest::newRow("bad escape") << QByteArray("[\"\\x\"]") << "line 1, column 4: syntax error while parsing value - invalid string: forbidden character after backslash";
  QTest::newRow("control char") << QByteArray("[\"a\nb\"]") << "line 1, column 4: syntax error while parsing value - invalid string: control character U+000A (LF) must be escaped";
  QTest::newRow("unterminated") << QByteArray("[\"abc") << "line 1, column 6: syntax error while parsing value - invalid string: missing closing quote";
  QTest::newRow("empty") << QByteArray("") << "line 1, column 1: syntax error while parsing value - unexpected end of input";
  QTest::newRow("lone surrogate") << QByteArray("[\"\\udc00\"]") << "line 1, column 8: syntax error while parsing value - invalid string: surrogate U+DC00..U+DFFF must follow U+D800..U+DBFF";
  QTest::newRow("bad UTF-8") << QByteArray("[\"caf\xc3(\"]") << "line 1, column 6: invalid UTF-8 in a string (bytes 0xC3 0x28): the file must be saved as UTF-8 text";
  QTest::newRow("UTF-16 surrogate in UTF-8") << QByteArray("[\"\xed\xa0\x80\"]") << "line 1, column 3: invalid UTF-8 in a string (bytes 0xED 0xA0)";
  QTest::newRow("byte outside a string") << QByteArray("[\xff]") << "line 1, column 2: syntax error while parsing value - invalid literal; last read: '[\\xFF'";
  QTest::newRow("deep") << QByteArray(300, '[') << "line 1, column 202: nesting deeper than 200 levels";
}

void TestProgram::jsonErrorsSayLineAndColumn() {
  QFETCH(QByteArray, text);
  QFETCH(QString, expected);
  try {
    parseJsonText(text.toStdString());
    QFAIL("parsed");
  } catch (const JsonSyntaxError& e) {
    QVERIFY2(QString::fromUtf8(e.what()).startsWith(expected), e.what());
    QVERIFY2(QString::fromUtf8(e.what()).toUtf8() == QByteArray(e.what()), "the message is not valid UTF-8");
  }
}

// The whole message of parseProgram for each kind of problem the strict loader promises to refuse.
void TestProgram::programJsonErrorsSayWhatAndWhere_data() {
  QTest::addColumn<QByteArray>("text");
  QTest::addColumn<QString>("expected");
  const std::string q = R"("target": {"q": [0,0,0,0,0,0,0]})";
  auto row = [](const char* name, const std::string& text, const char* expected) {
    QTest::newRow(name) << QByteArray::fromStdString(text) << QString::fromUtf8(expected);
  };
  row("syntax error",
      "{\"format\": \"rci-program\", \"version\": 1,\n \"robot\": \"xmate7_pro\"\n \"instructions\": []}",
      "not valid JSON: line 3, column 15: syntax error while parsing object - unexpected string literal; expected '}'");
  row("unknown member", withInstruction(R"({"type": "WAIT", "ms": 5, "speed": 0.5})"),
      "instruction 1 (WAIT), field \"speed\": unknown member (known here: type, name, ms)");
  row("unknown nested member", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,0,0,0,0,0], "qq": 1}, "speed": 0.5})"),
      "instruction 1 (MOVEJ), field \"target.qq\": unknown member (known here: q, pose, psi)");
  row("overflow", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,1e999,0,0,0,0]}, "speed": 0.5})"),
      "not valid JSON: line 1, column 120: number 1e999 is out of range: a double holds magnitudes up to about 1.8e308");
  row("duplicate key", withInstruction(R"({"type": "MOVEJ", )" + q + R"(, "speed": 0.5, "speed": 1})"),
      "not valid JSON: line 1, column 147: duplicate member \"speed\" (each name may appear once in an object)");
  row("bad UTF-8", withInstruction("{\"type\": \"WAIT\", \"name\": \"P\xe9\", \"ms\": 5}"),
      "not valid JSON: line 1, column 108: invalid UTF-8 in a string (bytes 0xE9 0x22): the file must be saved as UTF-8 text");
}

void TestProgram::programJsonErrorsSayWhatAndWhere() {
  QFETCH(QByteArray, text);
  QFETCH(QString, expected);
  QCOMPARE(errorOf(text.toStdString()), expected);
}

// Saving what was loaded gives the file back byte for byte: two spaces per level, arrays of numbers
// on one line, numbers as short as they round-trip (0, not 0.0), members in the documented order.
void TestProgram::savedTextKeepsItsLayout() {
  const std::string path = dataDir() + "/resources/programs/example.json";
  QCOMPARE(QString::fromStdString(programText(loadProgram(path))), QString::fromStdString(readFile(path)));
  Program p;
  p.robot = &xmate::model::robotSpec(XMATE3);
  Instruction wait;
  wait.type = InstructionType::kWait;
  wait.ms = 250;
  wait.name = "pause \"1\"";
  p.instructions.push_back(wait);
  p.instructions.push_back(moveJ(Target{}, 1.0));
  p.instructions.back().target.has_q = true;
  p.instructions.back().target.q = {0, -0.5, 1e-7, 1.5, 0, 2, 0};
  QCOMPARE(QString::fromStdString(programText(p)), QString::fromUtf8(R"({
  "format": "rci-program",
  "version": 2,
  "robot": "xmate3",
  "instructions": [
    {
      "type": "WAIT",
      "name": "pause \"1\"",
      "ms": 250
    },
    {
      "type": "MOVEJ",
      "target": {
        "q": [0, -0.5, 1e-07, 1.5, 0, 2, 0]
      },
      "speed": 1
    }
  ]
}
)"));
}

void TestProgram::programRoundTripsThroughAFile() {
  QTemporaryDir dir;
  const std::string path = (dir.path() + "/program.json").toStdString();
  const Program p = sampleProgram();
  saveProgram(path, p);
  const Program back = loadProgram(path);
  QVERIFY(sameProgram(p, back));
  // The text is the documented format.
  const QString text = QString::fromStdString(readFile(path));
  QVERIFY(text.contains("\"format\": \"rci-program\""));
  QVERIFY(text.contains("\"version\": 2"));
  QVERIFY(text.contains("\"robot\": \"xmate7_pro\""));
  QVERIFY(text.contains("\"signal\": \"DO0_1\""));
  QVERIFY(text.contains("\"signal\": \"DI1_1\""));
  // Saving what was loaded gives the same text.
  QCOMPARE(programText(back), programText(p));
}

// Version 2 records the tool and load the program was taught with; version 1 files still load,
// without them, and are saved as version 2.
void TestProgram::toolAndLoadRoundTrip() {
  Program p = sampleProgram();
  p.has_tool = true;
  p.tool = {0, -1, 0, 0.01, 1, 0, 0, 0, 0, 0, 1, 0.12, 0, 0, 0, 1};
  p.load.mass = 1.5;
  p.load.center = {0, 0.01, 0.05};
  p.load.inertia = {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.02};
  const Program back = parseProgram(programText(p));
  QVERIFY(sameProgram(p, back));
  QVERIFY(QString::fromStdString(programText(p)).contains("\"tool\": [0, -1, 0, 0.01, 1, 0, 0, 0, 0, 0, 1, 0.12, 0, 0, 0, 1]"));
  const Program old = parseProgram(withInstruction(""));
  QVERIFY(!old.has_tool);
  QVERIFY(QString::fromStdString(programText(old)).contains("\"version\": 2"));
  QVERIFY(!QString::fromStdString(programText(old)).contains("\"tool\""));
}

void TestProgram::exampleProgramLoads() {
  const Program p = loadProgram(dataDir() + "/resources/programs/example.json");
  QCOMPARE(p.robot, &xmate::model::robotSpec(XMATE7_PRO));
  QCOMPARE(p.instructions.size(), size_t(7));
  QCOMPARE(p.instructions[2].type, InstructionType::kMoveC);
}

// A KUKA program names its IO as the controller does, $OUT[n] / $IN[n]; the xMate's names are not
// its signals, nor are numbers outside 1..4096 or written with a leading zero.
void TestProgram::kukaSignalsAreNamedAsOnTheController() {
  const Program example = loadProgram(dataDir() + "/resources/programs/kr6_example.json");
  QCOMPARE(example.instructions[1].type, InstructionType::kSetDo);
  QCOMPARE(example.instructions[1].signal, 1);
  auto kukaWith = [](const std::string& instruction) {
    return R"({"format": "rci-program", "version": 2, "robot": "kr6_r900_sixx", "instructions": [)" + instruction +
           "]}";
  };
  const Program p = parseProgram(kukaWith(R"({"type": "SET_DO", "signal": "$OUT[4096]", "value": true},
      {"type": "WAIT_DI", "signal": "$IN[12]", "value": false, "timeout_ms": 500})"));
  QCOMPARE(p.instructions[0].signal, 4096);
  QCOMPARE(p.instructions[1].signal, 12);
  const std::string text = programText(p);
  QVERIFY(text.find(R"("signal": "$OUT[4096]")") != std::string::npos);
  QVERIFY(text.find(R"("signal": "$IN[12]")") != std::string::npos);
  QCOMPARE(parseProgram(text).instructions[1].signal, 12);
  for (const char* bad : {"DO0_0", "$OUT[0]", "$OUT[4097]", "$OUT[07]", "$OUT[]", "$OUT[1", "$IN[3]", "OUT[3]"}) {
    try {
      parseProgram(kukaWith(std::string(R"({"type": "SET_DO", "value": true, "signal": ")") + bad + "\"}"));
      QFAIL(bad);
    } catch (const ProgramError& e) {
      QCOMPARE(QString::fromUtf8(e.what()),
               QString("instruction 1 (SET_DO), field \"signal\": unknown signal \"%1\" for the KR 6 R900 sixx "
                       "(known: $OUT[1] to $OUT[4096])")
                   .arg(bad));
    }
  }
}

void TestProgram::badFieldsAreNamed_data() {
  QTest::addColumn<QString>("text");
  QTest::addColumn<QString>("expected");
  const std::string pose = kPoseJson;
  auto row = [](const char* name, const std::string& text, const char* expected) {
    QTest::newRow(name) << QString::fromStdString(text) << QString(expected);
  };
  row("not json", "{\"format\": ", "not valid JSON: line 1, column 12");
  row("unknown format", R"({"format": "other", "version": 1, "robot": "xmate7_pro", "instructions": []})",
      "field \"format\": expected \"rci-program\"");
  row("unknown version", R"({"format": "rci-program", "version": 3, "robot": "xmate7_pro", "instructions": []})",
      "field \"version\": unsupported version 3 (this RCI Studio reads versions 1 to 2)");
  const std::string identity = "[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0.1, 0, 0, 0, 1]";
  const std::string load = R"({"mass": 1.5, "center": [0, 0, 0.05], "inertia": [0, 0, 0, 0, 0, 0, 0, 0, 0]})";
  row("tool in version 1",
      R"({"format": "rci-program", "version": 1, "robot": "xmate7_pro", "tool": )" + identity +
          R"(, "load": )" + load + R"(, "instructions": []})",
      "field \"tool\": unknown member");
  row("tool without load",
      R"({"format": "rci-program", "version": 2, "robot": "xmate7_pro", "tool": )" + identity + R"(, "instructions": []})",
      "field \"load\": missing (a program records its tool and its load together)");
  row("tool not rigid",
      R"({"format": "rci-program", "version": 2, "robot": "xmate7_pro", "tool": [2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], "load": )" +
          load + R"(, "instructions": []})",
      "field \"tool\": not a homogeneous transform");
  row("negative mass",
      R"({"format": "rci-program", "version": 2, "robot": "xmate7_pro", "tool": )" + identity +
          R"(, "load": {"mass": -1, "center": [0, 0, 0], "inertia": [0, 0, 0, 0, 0, 0, 0, 0, 0]}, "instructions": []})",
      "field \"load.mass\": expected a mass in kg, 0 or more");
  row("unknown robot", withInstruction("", "xmate9"), "field \"robot\": unknown model \"xmate9\"");
  row("unknown type", withInstruction(R"({"type": "JUMP"})"), "instruction 1, field \"type\": unknown instruction type \"JUMP\"");
  row("type not string", withInstruction(R"({"type": 3})"), "instruction 1, field \"type\": expected a string, got a number");
  row("speed wrong type", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,0,0,0,0,0]}, "speed": "fast"})"),
      "instruction 1 (MOVEJ), field \"speed\": expected a number, got a string");
  row("speed too high", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,0,0,0,0,0]}, "speed": 1.5})"),
      "instruction 1 (MOVEJ), field \"speed\": expected a speed ratio in (0, 1]");
  row("speed zero", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,0,0,0,0,0]}, "speed": 0})"),
      "field \"speed\": expected a speed ratio in (0, 1]");
  row("speed missing", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,0,0,0,0,0]}})"),
      "instruction 1 (MOVEJ), field \"speed\": missing");
  row("q too short", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,0,0,0,0]}, "speed": 0.5})"),
      "field \"target.q\": expected an array of 7 numbers (joint angles in rad), got 6 elements");
  row("q element not number", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,null,0,0,0,0]}, "speed": 0.5})"),
      "field \"target.q[2]\": expected a number, got null");
  row("q overflow", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,1e400,0,0,0,0]}, "speed": 0.5})"),
      "number 1e400 is out of range");
  row("q NaN literal", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,NaN,0,0,0,0]}, "speed": 0.5})"),
      "NaN and Infinity are not JSON numbers");
  row("empty target", withInstruction(R"({"type": "MOVEL", "target": {}, "speed": 0.5})"),
      "instruction 1 (MOVEL), field \"target\": needs \"q\"");
  row("pose length", withInstruction(R"({"type": "MOVEL", "target": {"pose": [1,0,0]}, "speed": 0.5})"),
      "field \"target.pose\": expected an array of 16 numbers");
  row("pose not homogeneous",
      withInstruction(R"({"type": "MOVEL", "target": {"pose": [2,0,0,0.5, 0,1,0,0, 0,0,1,0.4, 0,0,0,1]}, "speed": 0.5})"),
      "instruction 1 (MOVEL), field \"target.pose\": not a homogeneous transform");
  row("pose bad last row",
      withInstruction(R"({"type": "MOVEL", "target": {"pose": [1,0,0,0.5, 0,1,0,0, 0,0,1,0.4, 0,0,1,1]}, "speed": 0.5})"),
      "field \"target.pose\": not a homogeneous transform");
  row("psi without pose", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,0,0,0,0,0], "psi": 0}, "speed": 0.5})"),
      "field \"target.psi\": an arm angle needs a \"pose\"");
  row("movec without via", withInstruction(R"({"type": "MOVEC", "target": {"pose": )" + pose + R"(}, "speed": 0.5})"),
      "instruction 1 (MOVEC), field \"via\": missing");
  row("unknown member", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,0,0,0,0,0]}, "sped": 0.5})"),
      "instruction 1 (MOVEJ), field \"sped\": unknown member");
  row("unknown do", withInstruction(R"({"type": "SET_DO", "signal": "DO7", "value": true})"),
      "instruction 1 (SET_DO), field \"signal\": unknown signal \"DO7\"");
  row("di as do", withInstruction(R"({"type": "SET_DO", "signal": "DI0_1", "value": true})"),
      "field \"signal\": unknown signal \"DI0_1\"");
  row("do value type", withInstruction(R"({"type": "SET_DO", "signal": "DO0_1", "value": 1})"),
      "field \"value\": expected true or false, got a number");
  row("wait negative", withInstruction(R"({"type": "WAIT", "ms": -5})"),
      "instruction 1 (WAIT), field \"ms\": expected a whole number in [0, 3600000]");
  row("wait fraction", withInstruction(R"({"type": "WAIT", "ms": 1.5})"), "field \"ms\": expected a whole number");
  row("wait_di no timeout", withInstruction(R"({"type": "WAIT_DI", "signal": "DI0_1", "value": true})"),
      "instruction 1 (WAIT_DI), field \"timeout_ms\": missing");
  row("six-axis q[6]", withInstruction(R"({"type": "MOVEJ", "target": {"q": [0,0,0,0,0,0,1]}, "speed": 0.5})", "xmate3"),
      "field \"target.q[6]\": must be 0 on the 6-axis xMate 3");
  row("second instruction",
      withInstruction(R"({"type": "WAIT", "ms": 5}, {"type": "MOVEL", "name": "P2", "target": {"pose": 5}, "speed": 0.5})"),
      "instruction 2 (MOVEL), field \"target.pose\": expected an array of 16 numbers");
  row("instructions not array", R"({"format": "rci-program", "version": 1, "robot": "xmate7_pro", "instructions": {}})",
      "field \"instructions\": expected an array, got an object");
  row("not an object", "[1, 2]", "a program is a JSON object");
}

void TestProgram::badFieldsAreNamed() {
  QFETCH(QString, text);
  QFETCH(QString, expected);
  const QString message = errorOf(text.toStdString());
  QVERIFY2(message.contains(expected), qPrintable("got: " + message));
}

void TestProgram::robotMismatchIsRefused() {
  const Program p = sampleProgram();
  requireRobot(p, XMATE7_PRO);
  try {
    requireRobot(p, XMATE3);
    QFAIL("accepted a program for another model");
  } catch (const ProgramError& e) {
    QVERIFY2(QString(e.what()).contains("taught for the xMate Pro 7 (xmate7_pro) but the robot is the xMate 3"),
             e.what());
  }
}

void TestProgram::atomicSaveReplacesAndLeavesNoTemporary() {
  QTemporaryDir dir;
  const std::string path = (dir.path() + "/p.json").toStdString();
  writeFileAtomically(path, "old");
  writeFileAtomically(path, "new contents");
  QCOMPARE(QString::fromStdString(readFile(path)), QString("new contents"));
  QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{"p.json"});
}

void TestProgram::atomicSaveKeepsPermissionsAndSymlinks() {
  QTemporaryDir dir;
  const QString real = dir.path() + "/programs/p.json";
  QVERIFY(QDir(dir.path()).mkdir("programs"));
  writeFileAtomically(real.toStdString(), "old");
  // A program shared in a lab group: read-write for the group, nothing for others.
  QVERIFY(QFile::setPermissions(real, QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup | QFile::WriteGroup));
  const QFile::Permissions before = QFile::permissions(real);
  // The operator opens it through a link in another folder (relative target).
  const QString link = dir.path() + "/current.json";
  QVERIFY(QFile::link("programs/p.json", link));
  writeFileAtomically(link.toStdString(), "new contents");
  QVERIFY2(QFileInfo(link).isSymLink(), "the link was replaced by a file");
  QCOMPARE(QString::fromStdString(readFile(real.toStdString())), QString("new contents"));
  QCOMPARE(QFile::permissions(real), before);
  QCOMPARE(QDir(dir.path() + "/programs").entryList(QDir::Files), QStringList{"p.json"});
  // A new file gets ordinary permissions (not mkstemp's 0600).
  const QString fresh = dir.path() + "/fresh.json";
  writeFileAtomically(fresh.toStdString(), "x");
  QVERIFY(QFile::permissions(fresh) & QFile::ReadOwner);
  QVERIFY(QFile::permissions(fresh) & QFile::WriteOwner);
}

void TestProgram::failedSaveKeepsThePreviousFile() {
  QTemporaryDir dir;
  // The target is a folder with something in it: the rename fails, nothing is lost or left behind.
  const QString target = dir.path() + "/taken";
  QVERIFY(QDir(dir.path()).mkdir("taken"));
  QFile keep(target + "/keep.txt");
  QVERIFY(keep.open(QIODevice::WriteOnly));
  keep.write("precious");
  keep.close();
  try {
    saveProgram(target.toStdString(), sampleProgram());
    QFAIL("saved over a folder");
  } catch (const std::runtime_error& e) {
    QVERIFY2(QString(e.what()).contains("previous file is unchanged"), e.what());
  }
  QCOMPARE(QString::fromStdString(readFile((target + "/keep.txt").toStdString())), QString("precious"));
  QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{});
  // A folder that does not exist: a clear error, no crash.
  QVERIFY_THROWS_EXCEPTION(std::runtime_error, saveProgram((dir.path() + "/no/such/p.json").toStdString(), sampleProgram()));
  QVERIFY_THROWS_EXCEPTION(std::runtime_error, loadProgram((dir.path() + "/missing.json").toStdString()));
}

void TestProgram::truncatedInputsNeverCrash() {
  const std::string text = programText(sampleProgram());
  int refused = 0;
  // text ends with "}\n": every prefix shorter than size() - 1 is incomplete.
  for (size_t n = 0; n + 1 < text.size(); ++n) {
    try {
      parseProgram(text.substr(0, n));
    } catch (const ProgramError&) {
      ++refused;
    }
  }
  QCOMPARE(refused, int(text.size()) - 1);
}

void TestProgram::garbledInputsNeverCrash() {
  const std::string text = programText(sampleProgram());
  std::mt19937 rng(12345);
  const char alphabet[] = "{}[],:\"\\0123456789.eE-+ truefalsnul\n\x01\xff";
  int parsed = 0;
  for (int round = 0; round < 3000; ++round) {
    std::string s = text;
    const int edits = 1 + int(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const size_t at = rng() % s.size();
      switch (rng() % 3) {
        case 0: s[at] = alphabet[rng() % (sizeof alphabet - 1)]; break;
        case 1: s.erase(at, 1 + rng() % 8); break;
        default: s.insert(at, 1, alphabet[rng() % (sizeof alphabet - 1)]); break;
      }
      if (s.empty()) s.push_back('{');
    }
    try {
      parseProgram(s);
      ++parsed;
    } catch (const ProgramError&) {
    }
  }
  qInfo("garbled inputs: %d of 3000 still parsed as programs, the rest were refused", parsed);
}

void TestProgram::recordingFromState() {
  RCI::robot::RobotState s;
  s.q = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7};
  s.toolTobase_pos_m = kPose;
  s.psi_m = 0.3;
  const Target t = targetFromState(s, XMATE7_PRO);
  QVERIFY(t.has_q && t.has_pose && t.has_psi);
  QCOMPARE(t.q, s.q);
  QCOMPARE(t.pose, kPose);
  QCOMPARE(t.psi, 0.3);
  const Target six = targetFromState(s, XMATE3);
  QCOMPARE(six.q[6], 0.0);
  QCOMPARE(six.psi, 0.0);
}

int runProgramTests(int argc, char** argv) {
  TestProgram t;
  return QTest::qExec(&t, argc, argv);
}

#include "test_program.moc"
