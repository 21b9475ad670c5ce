// SPDX-License-Identifier: Apache-2.0
// The RSI context and Ethernet config readers: the shipped samples read back as written (wiring,
// parameters by name, channels with their datagram element and attribute); real-file quirks are
// accepted (a byte-order mark, repeated ParamIDs, TYPE in any case, a placeholder IP_NUMBER); and
// every mistake the readers check is refused naming the file, the line and what is wrong.
#include <QtTest>

#include <string>

#include "rsi/config.h"
#include "rsi/digital_io.h"

using namespace xmate::rsi;

namespace {

std::string sample(const char* name) { return qEnvironmentVariable("RCI_DATA_DIR").toStdString() + "/resources/rsi/" + name; }

std::string configWith(const std::string& config, const std::string& send, const std::string& receive = "") {
  return "<ROOT>\n<CONFIG>\n" + config + "</CONFIG>\n<SEND><ELEMENTS>\n" + send + "</ELEMENTS></SEND>\n<RECEIVE><ELEMENTS>\n" +
         receive + "</ELEMENTS></RECEIVE>\n</ROOT>\n";
}

const std::string kConfig =
    "<IP_NUMBER>192.168.1.20</IP_NUMBER>\n<PORT>49152</PORT>\n<SENTYPE>ImFree</SENTYPE>\n<ONLYSEND>FALSE</ONLYSEND>\n";

QString errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return QString::fromUtf8(e.what());
  }
  return QStringLiteral("(accepted)");
}

}  // namespace

class TestRsiConfig : public QObject {
  Q_OBJECT

 private slots:
  void samplesReadBack();
  void realFileQuirksAreAccepted();
  void badEthernetConfigsAreNamed_data();
  void badEthernetConfigsAreNamed();
  void badContextsAreNamed_data();
  void badContextsAreNamed();
  void digitalSignalsFollowTheWiring();
};

void TestRsiConfig::samplesReadBack() {
  const Context context = readContext(sample("rci_axis_corr.rsi.xml"));
  QCOMPARE(int(context.objects.size()), 6);
  const Object* ethernet = context.ethernet();
  QVERIFY(ethernet);
  QCOMPARE(ethernet->id, std::string("ETHERNET1"));
  QCOMPARE(*ethernet->parameter("Timeout"), std::string("100"));
  QCOMPARE(int(ethernet->inputs.size()), 8);
  QCOMPARE(ethernet->inputs[6].out_object, std::string("STATUS1"));
  const Object* corr = context.find("AXISCORR1");
  QVERIFY(corr);
  QCOMPARE(corr->type_id, 33);
  QCOMPARE(*corr->parameter("UpperLimA3"), std::string("5"));
  QCOMPARE(corr->inputs[2].in_index, 3);
  QCOMPARE(corr->inputs[2].out_index, 3);
  QVERIFY(QString::fromStdString(context.ethernetConfigPath()).endsWith("resources/rsi/RSI_EthernetConfig.xml"));

  const EthernetConfig config = readEthernetConfig(context.ethernetConfigPath());
  QCOMPARE(config.ip, std::string("192.168.1.20"));
  QVERIFY(!config.ip_is_placeholder);
  QCOMPARE(config.port, uint16_t(49152));
  QCOMPARE(config.sentype, std::string("ImFree"));
  QVERIFY(!config.only_send);
  QCOMPARE(int(config.send.size()), 22);
  QCOMPARE(config.send[0].element, std::string("RIst"));
  QVERIFY(config.send[0].internal() && config.send[0].attribute.empty());
  QCOMPARE(config.send[5].element, std::string("Delay"));
  QCOMPARE(config.send[5].type, ValueType::kLong);
  QCOMPARE(config.send[6].element, std::string("GearTorque"));
  QCOMPARE(config.send[6].attribute, std::string("A1"));
  QCOMPARE(config.send[6].index, 1);
  QCOMPARE(int(config.receive.size()), 16);
  QCOMPARE(config.receive[0].element, std::string("EStr"));
  QCOMPARE(config.receive[1].tag, std::string("AK.A1"));
  QVERIFY(config.receive[1].hold_on);
  QCOMPARE(config.receive[7].type, ValueType::kBool);
  QVERIFY(config.receive[7].line > config.receive[6].line);
}

void TestRsiConfig::realFileQuirksAreAccepted() {
  // A byte-order mark, TYPE/Type/INDX in other cases, lower-case type names, a placeholder address,
  // no RECEIVE section (ONLYSEND), and repeated ParamIDs looked up by name.
  const std::string bom = "\xEF\xBB\xBF";
  const EthernetConfig c = parseEthernetConfig(
      bom + "<ROOT><CONFIG><IP_NUMBER>xxx.xxx.xxx.xxx</IP_NUMBER><PORT>6008</PORT><SENTYPE>KROSHU</SENTYPE>"
            "<ONLYSEND>true</ONLYSEND></CONFIG><SEND><ELEMENTS>"
            "<ELEMENT Tag=\"DEF_AIPos\" Type=\"double\" Indx=\"internal\"/>"
            "<ELEMENT TAG=\"Out.o1\" TYPE=\"Bool\" INDX=\"64\"/><ELEMENT TAG=\"Out.o2\" TYPE=\"BOOL\" INDX=\"63\"/>"
            "</ELEMENTS></SEND></ROOT>",
      "quirks.xml");
  QVERIFY(c.ip_is_placeholder);
  QVERIFY(c.only_send);
  QCOMPARE(int(c.send.size()), 3);
  QCOMPARE(c.send[0].element, std::string("AIPos"));
  QVERIFY(c.receive.empty());

  const Context ctx = parseContext(
      bom + "<RSIObjects><RSIObject ObjType=\"ETHERNET\" ObjID=\"E\"><Parameters>"
            "<Parameter Name=\"ConfigFile\" ParamID=\"1\" ParamValue=\"cfg.xml\"/>"
            "<Parameter Name=\"Timeout\" ParamID=\"1\" ParamValue=\"50\"/></Parameters></RSIObject>"
            "<RSIObject ObjType=\"POSCORR\" ObjID=\"P\"><Inputs><Input InIdx=\"1\" OutObjID=\"E\" OutIdx=\"1\"/></Inputs>"
            "<Parameters><Parameter Name=\"LowerLimX\" ParamID=\"1\" ParamValue=\"-5.0\"/>"
            "<Parameter Name=\"UpperLimX\" ParamID=\"1\" ParamValue=\"5.0\"/></Parameters></RSIObject></RSIObjects>",
      "/robot/quirks.rsi.xml");
  QCOMPARE(*ctx.ethernet()->parameter("Timeout"), std::string("50"));
  QCOMPARE(*ctx.find("P")->parameter("UpperLimX"), std::string("5.0"));
  QCOMPARE(ctx.ethernetConfigPath(), std::string("/robot/cfg.xml"));
}

void TestRsiConfig::badEthernetConfigsAreNamed_data() {
  QTest::addColumn<QString>("text");
  QTest::addColumn<QString>("expected");
  auto row = [](const char* name, const std::string& text, const char* expected) {
    QTest::newRow(name) << QString::fromStdString(text) << QString(expected);
  };
  const std::string ok = "<ELEMENT TAG=\"DEF_Delay\" TYPE=\"LONG\" INDX=\"INTERNAL\"/>\n";
  row("not xml", "<ROOT><CONFIG>\n</ROOT>", "bad.xml:2: not well-formed XML (mismatched tag");
  row("no config", "<ROOT>\n</ROOT>", "bad.xml:1: no <CONFIG> in <ROOT>");
  row("no port", "<ROOT>\n<CONFIG><IP_NUMBER>1.2.3.4</IP_NUMBER><SENTYPE>x</SENTYPE></CONFIG></ROOT>",
      "bad.xml:2: <CONFIG> has no <PORT>");
  row("port out of range", configWith("<IP_NUMBER>1.2.3.4</IP_NUMBER>\n<PORT>70000</PORT><SENTYPE>x</SENTYPE>", ok),
      "bad.xml:4: PORT \"70000\" is not a port number 1 to 65535");
  row("unknown type", configWith(kConfig, ok + "<ELEMENT TAG=\"X.a\" TYPE=\"FLOAT\" INDX=\"1\"/>\n"),
      "bad.xml:10: ELEMENT X.a: unknown TYPE \"FLOAT\"; give BOOL, STRING, LONG or DOUBLE");
  row("index 0", configWith(kConfig, "<ELEMENT TAG=\"X.a\" TYPE=\"LONG\" INDX=\"0\"/>\n"),
      "bad.xml:9: ELEMENT X.a: INDX=\"0\" is not a channel 1 to 64 or INTERNAL");
  row("index 65", configWith(kConfig, "<ELEMENT TAG=\"X.a\" TYPE=\"LONG\" INDX=\"65\"/>\n"),
      "INDX=\"65\" is not a channel 1 to 64 or INTERNAL");
  row("internal not built in", configWith(kConfig, "<ELEMENT TAG=\"Foo\" TYPE=\"LONG\" INDX=\"INTERNAL\"/>\n"),
      "ELEMENT Foo: INDX=\"INTERNAL\" is for the built-in values (DEF_RIst");
  row("built-in on a channel", configWith(kConfig, "<ELEMENT TAG=\"DEF_RIst\" TYPE=\"DOUBLE\" INDX=\"3\"/>\n"),
      "ELEMENT DEF_RIst: DEF_ values are built in; give INDX=\"INTERNAL\"");
  row("send-only built-in received", configWith(kConfig, ok, "<ELEMENT TAG=\"DEF_RIst\" TYPE=\"DOUBLE\" INDX=\"INTERNAL\"/>\n"),
      "INDX=\"INTERNAL\" is for the built-in values (DEF_EStr, DEF_Tech)");
  row("duplicate tag", configWith(kConfig, ok + "<ELEMENT TAG=\"A.b\" TYPE=\"LONG\" INDX=\"1\"/>\n<ELEMENT TAG=\"A.b\" TYPE=\"LONG\" INDX=\"2\"/>\n"),
      "bad.xml:11: SEND has the TAG A.b twice (also at line 10); remove one");
  row("parts disagree", configWith(kConfig, "", "<ELEMENT TAG=\"AK.A1\" TYPE=\"DOUBLE\" INDX=\"1\"/>\n<ELEMENT TAG=\"AK.A2\" TYPE=\"LONG\" INDX=\"2\"/>\n"),
      "bad.xml:12: RECEIVE: AK.A2 is LONG but AK.A1 (line 11) is DOUBLE; the attributes of one element share a TYPE");
  row("text and attributes", configWith(kConfig, "<ELEMENT TAG=\"A\" TYPE=\"LONG\" INDX=\"1\"/>\n<ELEMENT TAG=\"A.b\" TYPE=\"LONG\" INDX=\"2\"/>\n"),
      "<A> is both a text element and attributes");
  row("no tag", configWith(kConfig, "<ELEMENT TYPE=\"LONG\" INDX=\"1\"/>\n"), "bad.xml:9: ELEMENT without a TAG");
  row("bad holdon", configWith(kConfig, "", "<ELEMENT TAG=\"AK.A1\" TYPE=\"DOUBLE\" INDX=\"1\" HOLDON=\"yes\"/>\n"),
      "ELEMENT AK.A1: HOLDON=\"yes\" is not 0 or 1");
  row("bad onlysend", configWith("<IP_NUMBER>1.2.3.4</IP_NUMBER><PORT>1</PORT><SENTYPE>x</SENTYPE>\n<ONLYSEND>maybe</ONLYSEND>", ok),
      "bad.xml:4: ONLYSEND \"maybe\" is not TRUE or FALSE");
}

void TestRsiConfig::badEthernetConfigsAreNamed() {
  QFETCH(QString, text);
  QFETCH(QString, expected);
  const QString error = errorOf([&] { parseEthernetConfig(text.toStdString(), "bad.xml"); });
  QVERIFY2(error.contains(expected), qPrintable(error));
}

void TestRsiConfig::badContextsAreNamed_data() {
  QTest::addColumn<QString>("text");
  QTest::addColumn<QString>("expected");
  const QString ethernet = QStringLiteral(
      "<RSIObject ObjType=\"ETHERNET\" ObjID=\"E1\"><Parameters><Parameter Name=\"ConfigFile\" ParamValue=\"c.xml\"/>"
      "</Parameters></RSIObject>\n");
  QTest::newRow("no ethernet") << QStringLiteral("<RSIObjects>\n</RSIObjects>")
                               << QStringLiteral("ctx.rsi.xml:1: no ETHERNET object: this context exchanges nothing with the PC");
  QTest::newRow("no config file") << QStringLiteral("<RSIObjects>\n<RSIObject ObjType=\"ETHERNET\" ObjID=\"E1\"/>\n</RSIObjects>")
                                  << QStringLiteral("ctx.rsi.xml:2: E1 has no ConfigFile parameter");
  QTest::newRow("no type") << QStringLiteral("<RSIObjects>\n") + ethernet + QStringLiteral("<RSIObject ObjID=\"X\"/>\n</RSIObjects>")
                           << QStringLiteral("ctx.rsi.xml:3: an RSIObject without ObjType");
  QTest::newRow("duplicate id") << QStringLiteral("<RSIObjects>\n") + ethernet +
                                       QStringLiteral("<RSIObject ObjType=\"SOURCE\" ObjID=\"E1\"/>\n</RSIObjects>")
                                << QStringLiteral("ctx.rsi.xml:3: ObjID E1 is used twice (also at line 2)");
  QTest::newRow("unknown wiring") << QStringLiteral("<RSIObjects>\n") + ethernet +
                                         QStringLiteral("<RSIObject ObjType=\"AXISCORR\" ObjID=\"C1\"><Inputs>"
                                                        "<Input InIdx=\"1\" OutObjID=\"ETHERNET9\" OutIdx=\"1\"/></Inputs></RSIObject>\n</RSIObjects>")
                                  << QStringLiteral("ctx.rsi.xml:3: input 1 of C1 is wired to ETHERNET9, which is not an object of this context");
  QTest::newRow("bad index") << QStringLiteral("<RSIObjects>\n") + ethernet +
                                    QStringLiteral("<RSIObject ObjType=\"AXISCORR\" ObjID=\"C1\"><Inputs>\n"
                                                   "<Input InIdx=\"0\" OutObjID=\"E1\" OutIdx=\"1\"/></Inputs></RSIObject>\n</RSIObjects>")
                             << QStringLiteral("ctx.rsi.xml:4: an Input of C1 needs InIdx, OutObjID and OutIdx (indices from 1)");
  QTest::newRow("missing file") << QString() << QStringLiteral("cannot open the RSI context");
}

void TestRsiConfig::badContextsAreNamed() {
  QFETCH(QString, text);
  QFETCH(QString, expected);
  const QString error = text.isEmpty() ? errorOf([] { readContext("/nonexistent/ctx.rsi.xml"); })
                                       : errorOf([&] { parseContext(text.toStdString(), "ctx.rsi.xml"); });
  QVERIFY2(error.contains(expected), qPrintable(error));
}

// Which $IN / $OUT the PC reaches: DIGIN outputs wired into the ETHERNET object's inputs (SEND
// elements), ETHERNET outputs (RECEIVE elements) wired into DIGOUT inputs, numbered from Index.
void TestRsiConfig::digitalSignalsFollowTheWiring() {
  const Context replay = readContext(sample("rci_replay.rsi.xml"));
  const DigitalIoMap map = digitalIoMap(replay, readEthernetConfig(replay.ethernetConfigPath()));
  QCOMPARE(int(map.inputs.size()), 8);
  QCOMPARE(int(map.outputs.size()), 8);
  QCOMPARE(map.input(3)->tag, std::string("Digin.i3"));
  QCOMPARE(map.input(3)->object, std::string("DIGIN1"));
  QCOMPARE(map.output(8)->element, std::string("Digout"));
  QCOMPARE(map.output(8)->attribute, std::string("o8"));
  QVERIFY(!map.input(9) && !map.output(0));
  // The sample without DIGIN/DIGOUT wires none.
  const Context plain = readContext(sample("rci_axis_corr.rsi.xml"));
  const DigitalIoMap none = digitalIoMap(plain, readEthernetConfig(plain.ethernetConfigPath()));
  QVERIFY(none.inputs.empty() && none.outputs.empty());

  // Index moves the numbers; a wire to a channel the config lacks is left out.
  const EthernetConfig config = parseEthernetConfig(
      configWith(kConfig, "<ELEMENT TAG=\"In.a\" TYPE=\"BOOL\" INDX=\"1\"/>\n<ELEMENT TAG=\"In.b\" TYPE=\"BOOL\" INDX=\"2\"/>\n",
                 "<ELEMENT TAG=\"Out\" TYPE=\"BOOL\" INDX=\"3\"/>\n"),
      "io.xml");
  auto context = [](const std::string& index) {
    return "<RSIObjects>\n"
           "<RSIObject ObjType=\"DIGIN\" ObjID=\"DI\"><Parameters><Parameter Name=\"Index\" ParamValue=\"" +
           index +
           "\"/></Parameters></RSIObject>\n"
           "<RSIObject ObjType=\"ETHERNET\" ObjID=\"E\"><Inputs><Input InIdx=\"1\" OutObjID=\"DI\" OutIdx=\"2\"/>"
           "<Input InIdx=\"5\" OutObjID=\"DI\" OutIdx=\"1\"/></Inputs><Parameters><Parameter Name=\"ConfigFile\" "
           "ParamValue=\"io.xml\"/></Parameters></RSIObject>\n"
           "<RSIObject ObjType=\"DIGOUT\" ObjID=\"DO\"><Inputs><Input InIdx=\"4\" OutObjID=\"E\" OutIdx=\"3\"/>"
           "</Inputs><Parameters><Parameter Name=\"Index\" ParamValue=\"" +
           index + "\"/></Parameters></RSIObject>\n</RSIObjects>\n";
  };
  const DigitalIoMap moved = digitalIoMap(parseContext(context("17"), "io.rsi.xml"), config);
  QCOMPARE(int(moved.inputs.size()), 1);  // InIdx 5 has no SEND element: left out
  QCOMPARE(moved.inputs[0].signal, 18);   // DIGIN output 2 from Index 17
  QCOMPARE(moved.inputs[0].tag, std::string("In.a"));
  QCOMPARE(int(moved.outputs.size()), 1);
  QCOMPARE(moved.outputs[0].signal, 20);  // DIGOUT input 4 from Index 17
  QCOMPARE(moved.outputs[0].tag, std::string("Out"));
  QCOMPARE(errorOf([&] { digitalIoMap(parseContext(context("2.5"), "io.rsi.xml"), config); }),
           QStringLiteral("io.rsi.xml:2: DI (DIGIN): Index 2.5 is not an input/output number; give the first one, from 1"));
  QCOMPARE(errorOf([&] { digitalIoMap(parseContext(context("one"), "io.rsi.xml"), config); }),
           QStringLiteral("io.rsi.xml:2: DI (DIGIN): parameter Index=\"one\" is not a number; give a decimal number such as "
                          "5 or -2.5"));
}

QTEST_MAIN(TestRsiConfig)
#include "test_rsi_config.moc"
