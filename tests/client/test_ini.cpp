// SPDX-License-Identifier: Apache-2.0
// INIParser (inih behind the vendor-compatible class): sections, keys, comments, whitespace, quotes,
// typed getters, missing keys, indented lines, a UTF-8 byte order mark, and the line-numbered error
// for a malformed file.
#include <QtTest>

#include <QTemporaryDir>

#include <fstream>

#include <xmate/ini.h>

using xmate::INIParser;

class TestIni : public QObject {
  Q_OBJECT

 private slots:
  void readsTheManualsNetworkSection();
  void commentsWhitespaceAndQuotes();
  void typedGetters();
  void missingFileAndKeys();
  void malformedLineIsReportedWithItsNumber();
  void indentedLinesAreKeysNotContinuations();
  void byteOrderMarkAndLongLines();

 private:
  std::string write(const char* text);
  QTemporaryDir dir_;
  int files_ = 0;
};

std::string TestIni::write(const char* text) {
  const std::string path = dir_.filePath(QString("f%1.ini").arg(files_++)).toStdString();
  std::ofstream(path) << text;
  return path;
}

void TestIni::readsTheManualsNetworkSection() {
  INIParser ini;
  QVERIFY(ini.ReadINI(write("[network]\nip=192.168.0.160\nport=1337\n")));
  QCOMPARE(QString::fromStdString(ini.GetString("network", "ip")), QString("192.168.0.160"));
  QCOMPARE(ini.GetInt("network", "port"), 1337);
}

void TestIni::commentsWhitespaceAndQuotes() {
  INIParser ini;
  QVERIFY(ini.ReadINI(write("; a comment\n# another\n\n  [ network ]  \n  ip =  10.0.0.2  ; trailing\n"
                            "name = \"xMate 7\"\nurl = http://x/#frag\n[other]\nip=1.2.3.4\r\n")));
  QCOMPARE(QString::fromStdString(ini.GetString("network", "ip")), QString("10.0.0.2"));
  QCOMPARE(QString::fromStdString(ini.GetString("network", "name")), QString("xMate 7"));
  QCOMPARE(QString::fromStdString(ini.GetString("network", "url")), QString("http://x/#frag"));
  QCOMPARE(QString::fromStdString(ini.GetString("other", "ip")), QString("1.2.3.4"));
}

void TestIni::typedGetters() {
  INIParser ini;
  QVERIFY(ini.ReadINI(write("[a]\ni=-42\nhex=0x10\nd=2.5e-3\nb1=true\nb2=ON\nb3=0\nbad=12abc\n")));
  QCOMPARE(ini.GetInt("a", "i"), -42);
  QCOMPARE(ini.GetInt("a", "hex"), 16);
  QCOMPARE(ini.GetDouble("a", "d"), 2.5e-3);
  QVERIFY(ini.GetBool("a", "b1"));
  QVERIFY(ini.GetBool("a", "b2"));
  QVERIFY(!ini.GetBool("a", "b3"));
  QCOMPARE(ini.GetInt("a", "bad"), 0);
  QCOMPARE(ini.GetDouble("a", "bad"), 0.0);
}

void TestIni::missingFileAndKeys() {
  INIParser ini;
  QVERIFY(!ini.ReadINI(dir_.filePath("nope.ini").toStdString()));
  QVERIFY(QString::fromStdString(ini.LastError()).contains("cannot open"));
  QVERIFY(ini.ReadINI(write("[s]\nk=v\n")));
  QCOMPARE(QString::fromStdString(ini.GetString("s", "missing")), QString());
  QCOMPARE(QString::fromStdString(ini.GetString("missing", "k")), QString());
  QCOMPARE(ini.GetInt("s", "missing"), 0);
  QCOMPARE(ini.GetDouble("s", "missing"), 0.0);
  QVERIFY(!ini.GetBool("s", "missing"));
}

void TestIni::malformedLineIsReportedWithItsNumber() {
  INIParser ini;
  QVERIFY(!ini.ReadINI(write("[s]\nk=v\njust words\n")));
  QVERIFY2(QString::fromStdString(ini.LastError()).contains(":3: expected key = value"), ini.LastError().c_str());
  QVERIFY(!ini.ReadINI(write("[unclosed\n")));
  QVERIFY(QString::fromStdString(ini.LastError()).contains(":1: a section header"));
}

void TestIni::indentedLinesAreKeysNotContinuations() {
  INIParser ini;
  QVERIFY(ini.ReadINI(write("[network]\n  ip = 10.0.0.3\n\tport = 1337 # the RCI port\n  name = a;b ; comment\n")));
  QCOMPARE(QString::fromStdString(ini.GetString("network", "ip")), QString("10.0.0.3"));
  QCOMPARE(ini.GetInt("network", "port"), 1337);
  QCOMPARE(QString::fromStdString(ini.GetString("network", "name")), QString("a;b"));
  // Later values of a key replace earlier ones.
  QVERIFY(ini.ReadINI(write("[s]\nk = 1\nk = 2\n")));
  QCOMPARE(ini.GetInt("s", "k"), 2);
}

void TestIni::byteOrderMarkAndLongLines() {
  INIParser ini;
  QVERIFY(ini.ReadINI(write("\xEF\xBB\xBF[network]\nip=127.0.0.1\n")));
  QCOMPARE(QString::fromStdString(ini.GetString("network", "ip")), QString("127.0.0.1"));
  const std::string long_line = "[s]\nk=" + std::string(300, 'x') + "\n";
  QVERIFY(!ini.ReadINI(write(long_line.c_str())));
  QVERIFY2(QString::fromStdString(ini.LastError()).contains(":2: the line is longer than"), ini.LastError().c_str());
  QVERIFY(!ini.ReadINI(write("[s]\n= value\n")));
  QVERIFY2(QString::fromStdString(ini.LastError()).contains(":2: expected key = value, got '= value'"),
           ini.LastError().c_str());
}

QTEST_APPLESS_MAIN(TestIni)
#include "test_ini.moc"
