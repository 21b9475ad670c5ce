// SPDX-License-Identifier: Apache-2.0
// The RSI datagram codec on the sample Ethernet config: a <Rob> as a KRC sends it is read into its
// slots (built-in values expanded, numbers in every form public code writes, Type in any case, a
// 64-bit IPOC kept verbatim, unknown elements counted); malformed and oversized datagrams are
// refused with a reason and leave the last values; <Sen> carries every RECEIVE element, escapes
// text, echoes the IPOC and stays under 1 KB; and neither allocates once set up.
#include <QtTest>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <random>
#include <string>

#include "../planning/allocation_counter.h"
#include "rsi/codec.h"
#include "rsi/config.h"

using namespace xmate::rsi;

namespace {

EthernetConfig sampleConfig() {
  return readEthernetConfig(qEnvironmentVariable("RCI_DATA_DIR").toStdString() + "/resources/rsi/RSI_EthernetConfig.xml");
}

// A <Rob> for the sample config, as a KRC writes it (4 decimals, no declaration).
std::string robDatagram(const std::string& ipoc = "4208", const std::string& type = "Type") {
  return "<Rob " + type +
         "=\"ImFree\"><RIst X=\"445.0000\" Y=\"0.0000\" Z=\"810.0000\" A=\"180.0000\" B=\"0.0000\" C=\"180.0000\" />"
         "<RSol X=\"445.0000\" Y=\"0.0000\" Z=\"810.0000\" A=\"180.0000\" B=\"0.0000\" C=\"180.0000\" />"
         "<AIPos A1=\"0.0000\" A2=\"-90.0000\" A3=\"90.0000\" A4=\"0.0000\" A5=\"90.0000\" A6=\"0.0000\" />"
         "<ASPos A1=\"0.0\" A2=\"-90.0\" A3=\"90.0\" A4=\"-0.000000\" A5=\"90\" A6=\"1e-05\" />"
         "<MACur A1=\"0.12\" A2=\"-1.5\" A3=\"0.8\" A4=\"0\" A5=\"0.01\" A6=\"0\" />"
         "<Delay D=\"3\" />"
         "<GearTorque A1=\"1.5\" A2=\"-60.25\" A3=\"20\" A4=\"+0.5\" A5=\"3E+01\" A6=\"0\" />"
         "<Status>2</Status><Override>100</Override><Extra Foo=\"1\" /><IPOC>" +
         ipoc + "</IPOC></Rob>";
}

}  // namespace

class TestRsiCodec : public QObject {
  Q_OBJECT

 private slots:
  void robIsReadIntoItsSlots();
  void badDatagramsAreRefusedAndKeepTheLastValues_data();
  void badDatagramsAreRefusedAndKeepTheLastValues();
  void numbersAreReadExactlyAsFromChars();
  void senCarriesTheReceiveElements();
  void neitherAllocatesOnceSetUp();
};

void TestRsiCodec::robIsReadIntoItsSlots() {
  RobDecoder d(sampleConfig());
  QCOMPARE(int(d.layout().size()), 6 + 6 + 6 + 6 + 6 + 1 + 6 + 2 + 8);
  QVERIFY2(d.decode(robDatagram("18446744073709551615", "TYPE")), d.reason());
  QCOMPARE(d.ipoc(), uint64_t(18446744073709551615ull));
  QCOMPARE(d.ipocText(), std::string_view("18446744073709551615"));
  QCOMPARE(d.type(), std::string_view("ImFree"));
  QCOMPARE(d.value(d.slot("RIst", "X")), 445.0);
  QCOMPARE(d.value(d.slot("AIPos", "A2")), -90.0);
  QCOMPARE(d.value(d.slot("ASPos", "A6")), 1e-05);
  QCOMPARE(d.value(d.slot("ASPos", "A5")), 90.0);
  QCOMPARE(d.value(d.slot("Delay", "D")), 3.0);
  QCOMPARE(d.value(d.slot("GearTorque", "A2")), -60.25);
  QCOMPARE(d.value(d.slot("GearTorque", "A4")), 0.5);
  QCOMPARE(d.value(d.slot("GearTorque", "A5")), 30.0);
  QCOMPARE(d.value(d.slot("Status")), 2.0);
  QCOMPARE(d.value(d.slot("Override")), 100.0);
  QVERIFY(d.seen(d.slot("MACur", "A1")));
  QCOMPARE(d.unknownCount(), 2u);  // <Extra> and its Foo
  // Whitespace, another order of attributes and elements, a declaration: the same values.
  QVERIFY2(d.decode("<?xml version=\"1.0\"?>\n<Rob Type=\"ImFree\">\n  <IPOC> 7 </IPOC>\n  <Delay   D = \"4\"/>\n"
                    "  <Status>\n 1 \n</Status>\n</Rob>\n"),
           d.reason());
  QCOMPARE(d.ipoc(), uint64_t(7));
  QCOMPARE(d.value(d.slot("Delay", "D")), 4.0);
  QCOMPARE(d.value(d.slot("Status")), 1.0);
  QCOMPARE(d.value(d.slot("GearTorque", "A2")), -60.25);  // not in this datagram: kept
}

void TestRsiCodec::badDatagramsAreRefusedAndKeepTheLastValues_data() {
  QTest::addColumn<QString>("datagram");
  QTest::addColumn<QString>("reason");
  QTest::newRow("truncated") << QString::fromStdString(robDatagram().substr(0, 200)) << "Error parsing element attribute";
  QTest::newRow("not xml") << "hello" << "No document element found";
  QTest::newRow("empty") << "" << "No document element found";
  QTest::newRow("not Rob") << "<Sen Type=\"ImFree\"><IPOC>1</IPOC></Sen>" << "not a <Rob> datagram";
  QTest::newRow("no IPOC") << "<Rob Type=\"ImFree\"><Delay D=\"1\"/></Rob>" << "the datagram has no <IPOC>";
  QTest::newRow("negative IPOC") << "<Rob><IPOC>-5</IPOC></Rob>" << "<IPOC> is not an unsigned 64-bit number";
  QTest::newRow("IPOC overflow") << "<Rob><IPOC>18446744073709551616</IPOC></Rob>" << "<IPOC> is not an unsigned 64-bit number";
  QTest::newRow("not a number") << "<Rob><Delay D=\"many\"/><IPOC>1</IPOC></Rob>"
                                << "a value is not a number of the type the Ethernet config gives it";
  QTest::newRow("nan") << "<Rob><Delay D=\"nan\"/><IPOC>1</IPOC></Rob>"
                       << "a value is not a number of the type the Ethernet config gives it";
  QTest::newRow("oversized") << QString(9000, QLatin1Char(' ')) << "the datagram is longer than 8 KB";
  // Entities a datagram declares are not expanded: the bomb stays ten short words, not a number.
  QTest::newRow("entity bomb") << "<!DOCTYPE r [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;&a;\">]>"
                                  "<Rob><Status>&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;</Status><IPOC>1</IPOC></Rob>"
                               << "a value is not a number of the type the Ethernet config gives it";
  QTest::newRow("long value") << "<Rob><Status>" + QString(200, QLatin1Char('7')) + "</Status><IPOC>1</IPOC></Rob>"
                              << "a value is longer than the codec keeps";
}

void TestRsiCodec::badDatagramsAreRefusedAndKeepTheLastValues() {
  QFETCH(QString, datagram);
  QFETCH(QString, reason);
  RobDecoder d(sampleConfig());
  QVERIFY(d.decode(robDatagram("99")));
  QVERIFY(!d.decode(datagram.toStdString()));
  QVERIFY2(QString::fromUtf8(d.reason()).contains(reason), d.reason());
  QCOMPARE(d.ipoc(), uint64_t(99));
  QCOMPARE(d.value(d.slot("Delay", "D")), 3.0);
  QVERIFY(d.decode(robDatagram("100")));  // and the next good one is read
  QCOMPARE(d.ipoc(), uint64_t(100));
}

// The decoder reads plain decimals ("-35.250000") on a fast path of its own; every number must
// still come out as the very double std::from_chars makes of the same text.
void TestRsiCodec::numbersAreReadExactlyAsFromChars() {
  RobDecoder d(sampleConfig());
  const int slot = d.slot("GearTorque", "A1");
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> magnitude(-7.0, 7.0);
  const char* const formats[] = {"%.0f", "%.1f", "%.4f", "%.6f", "%.9f", "%.12f", "%.17g", "%g", "%.3e"};
  int checked = 0;
  for (int k = 0; k < 20000; ++k) {
    const double v = std::copysign(std::pow(10.0, magnitude(random)), double(random() % 2) - 0.5);
    char text[64];
    std::snprintf(text, sizeof text, formats[k % std::size(formats)], v);
    double expected = 0;
    std::from_chars(text, text + std::strlen(text), expected);
    const std::string rob = std::string("<Rob><GearTorque A1=\"") + text + "\"/><IPOC>1</IPOC></Rob>";
    QVERIFY2(d.decode(rob), d.reason());
    const double got = d.value(slot);
    if (std::memcmp(&expected, &got, sizeof expected) != 0)
      QFAIL(qPrintable(QStringLiteral("\"%1\" read as %2, from_chars gives %3")
                           .arg(text)
                           .arg(d.value(slot), 0, 'g', 17)
                           .arg(expected, 0, 'g', 17)));
    ++checked;
  }
  QCOMPARE(checked, 20000);
  // The edges of the fast path: 15 digits (taken), 16 (left to from_chars), a bare point, signs.
  const std::pair<const char*, double> edges[] = {
      {"123456789.012345", 123456789.012345}, {"1234567890.123456", 1234567890.123456}, {"-0.000000", -0.0},
      {"5.", 5.0}, {".5", 0.5}, {"-.5", -0.5}, {"007.250", 7.25}, {"1e-05", 1e-05}};
  for (const auto& [text, value] : edges) {
    QVERIFY2(d.decode(std::string("<Rob><GearTorque A1=\"") + text + "\"/><IPOC>1</IPOC></Rob>"), text);
    QCOMPARE(d.value(slot), value);
    QCOMPARE(std::signbit(d.value(slot)), std::signbit(value));
  }
  for (const char* bad : {"1.2.3", "-", "1-2", "--1", "1..2"})
    QVERIFY2(!d.decode(std::string("<Rob><GearTorque A1=\"") + bad + "\"/><IPOC>1</IPOC></Rob>"), bad);
}

void TestRsiCodec::senCarriesTheReceiveElements() {
  const EthernetConfig config = sampleConfig();
  SenEncoder e(config, 4);
  for (int i = 1; i <= 6; ++i) e.set(e.slot("AK", "A" + std::to_string(i)), 0.5 * i - 1.0);
  e.set(e.slot("Stop"), 1);
  e.setText(e.slot("EStr"), "J3 > limit & \"stop\"");
  char out[kMaxSenBytes];
  const size_t n = e.encode("18446744073709551615", out, sizeof out);
  QVERIFY(n > 0 && n < kMaxSenBytes);
  const std::string sen(out, n);
  QCOMPARE(sen, std::string("<Sen Type=\"ImFree\"><EStr>J3 &gt; limit &amp; &quot;stop&quot;</EStr>"
                            "<AK A1=\"-0.5000\" A2=\"0.0000\" A3=\"0.5000\" A4=\"1.0000\" A5=\"1.5000\" A6=\"2.0000\" />"
                            "<Stop>1</Stop><Digout o1=\"0\" o2=\"0\" o3=\"0\" o4=\"0\" o5=\"0\" o6=\"0\" o7=\"0\" o8=\"0\" /><IPOC>18446744073709551615</IPOC></Sen>"));
  // Well-formed, with the text back as it was set.
  const XmlElement parsed = parseXml(sen, "sen");
  QCOMPARE(parsed.child("EStr")->text, std::string("J3 > limit & \"stop\""));
  QCOMPARE(parsed.child("IPOC")->text, std::string("18446744073709551615"));
  // Too small a buffer: nothing half-written is offered.
  QCOMPARE(e.encode("1", out, 40), size_t(0));
}

void TestRsiCodec::neitherAllocatesOnceSetUp() {
  const EthernetConfig config = sampleConfig();
  RobDecoder d(config);
  SenEncoder e(config);
  char out[kMaxSenBytes];
  const std::string good = robDatagram("123456789");
  const std::string bad = robDatagram().substr(0, 300);
  QVERIFY(d.decode(good));  // the first parse touches the arena's pages; it allocates nothing either
  const std::size_t before = planning_test::allocationCount();
  size_t sent = 0;
  for (int i = 0; i < 2000; ++i) {
    if (!d.decode(i % 10 == 9 ? std::string_view(bad) : std::string_view(good))) continue;
    e.set(e.slot("AK", "A1"), d.value(d.slot("AIPos", "A1")) + 0.001 * i);
    sent += e.encode(d.ipocText(), out, sizeof out);
  }
  QCOMPARE(planning_test::allocationCount() - before, std::size_t(0));
  QVERIFY(sent > 0);
}

QTEST_MAIN(TestRsiCodec)
#include "test_rsi_codec.moc"
