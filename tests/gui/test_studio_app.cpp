// SPDX-License-Identifier: Apache-2.0
// test_studio_app (under xvfb-run): runs the rci-studio program -- its option handling (the xMate's
// and the KUKA's), and --screenshot rendering the whole window with the 3D view to a PNG.
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <set>

namespace {

struct Run {
  int code = -1;
  QString out, err;
};

Run runStudio(const QStringList& arguments, int limit_ms = 120000) {
  static QTemporaryDir state;  // the event log of these runs goes here, not to the user's state folder
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  environment.insert(QStringLiteral("XDG_STATE_HOME"), state.path());
  QProcess process;
  process.setProcessEnvironment(environment);
  process.start(QStringLiteral(RCI_STUDIO_PATH), arguments);
  Run run;
  if (!process.waitForFinished(limit_ms)) {
    process.kill();
    process.waitForFinished();
    run.err = QStringLiteral("rci-studio did not finish");
    return run;
  }
  run.code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
  run.out = QString::fromLocal8Bit(process.readAllStandardOutput());
  run.err = QString::fromLocal8Bit(process.readAllStandardError());
  return run;
}

// The sample RSI Ethernet config (two sample contexts beside it use it).
QString sampleRsiConfig() {
  return QDir(qEnvironmentVariable("RCI_DATA_DIR", QStringLiteral("."))).filePath(QStringLiteral("resources/rsi/RSI_EthernetConfig.xml"));
}

// Number of distinct colours in a grid of samples over rect: a rendered scene has many.
int distinctColours(const QImage& image, const QRect& rect) {
  std::set<QRgb> colours;
  for (int y = rect.top(); y < rect.bottom(); y += 7)
    for (int x = rect.left(); x < rect.right(); x += 7) colours.insert(image.pixel(x, y));
  return int(colours.size());
}

}  // namespace

class TestStudioApp : public QObject {
  Q_OBJECT

 private slots:
  void helpExitsZero() {
    const Run run = runStudio({"--help"});
    QCOMPARE(run.code, 0);
    QVERIFY(run.out.contains("--screenshot <FILE>"));
    QVERIFY(run.out.contains("--robot <HOST:PORT>"));
    QVERIFY(run.out.contains("Usage: rci-studio [options]"));
    QVERIFY2(run.out.contains("--ft-sensor <HOST[:PORT]>"), qPrintable(run.out));
    QVERIFY(run.out.contains("--context <FILE>"));
    QVERIFY(run.out.contains("kr6_r900_sixx"));
    QVERIFY(run.out.contains("rsi:FILE"));
    const Run shortHelp = runStudio({"-h"});
    QCOMPARE(shortHelp.code, 0);
    QCOMPARE(shortHelp.out, run.out);
    const Run all = runStudio({"--help-all"});
    QCOMPARE(all.code, 0);
    QVERIFY2(all.out.contains("--screenshot <FILE>"), qPrintable(all.out));
    const Run version = runStudio({"--version"});
    QCOMPARE(version.code, 0);
    QVERIFY2(version.out.startsWith("rci-studio "), qPrintable(version.out));
  }
  void badOptionsExitTwo() {
    const Run unknown = runStudio({"--frobnicate"});
    QCOMPARE(unknown.code, 2);
    QVERIFY2(unknown.err.contains("unknown option \"--frobnicate\""), qPrintable(unknown.err));
    const Run model = runStudio({"--model", "ur5"});
    QCOMPARE(model.code, 2);
    QVERIFY2(model.err.contains("xmate7_pro"), qPrintable(model.err));
    const Run robot = runStudio({"--robot", "10.0.0.1"});
    QCOMPARE(robot.code, 2);
    QVERIFY2(robot.err.contains("HOST:PORT"), qPrintable(robot.err));
    const Run missing = runStudio({"--screenshot"});
    QCOMPARE(missing.code, 2);
    QVERIFY2(missing.err.contains("--screenshot needs a value"), qPrintable(missing.err));
    const Run next_option = runStudio({"--screenshot", "--lockstep"});
    QCOMPARE(next_option.code, 2);
    QVERIFY2(next_option.err.contains("--screenshot needs a value"), qPrintable(next_option.err));
    // --opt=value is the same as --opt value.
    const Run equals = runStudio({"--model=ur5"});
    QCOMPARE(equals.code, 2);
    QVERIFY2(equals.err.contains("unknown model \"ur5\""), qPrintable(equals.err));
    const Run flag_value = runStudio({"--lockstep=1"});
    QCOMPARE(flag_value.code, 2);
    QVERIFY2(flag_value.err.contains("--lockstep"), qPrintable(flag_value.err));
    const Run stray = runStudio({"robot.png"});
    QCOMPARE(stray.code, 2);
    QVERIFY2(stray.err.contains("unexpected argument \"robot.png\""), qPrintable(stray.err));
    // --screenshot and --robot exclude each other.
    const Run both = runStudio({"--screenshot", "x.png", "--robot", "10.0.0.1:1337"});
    QCOMPARE(both.code, 2);
    QVERIFY2(both.err.contains("--screenshot uses the built-in simulator; leave out --robot"), qPrintable(both.err));
  }
  void badKukaOptionsSayWhatToType() {
    const QString config = sampleRsiConfig();
    QVERIFY2(QFileInfo::exists(config), qPrintable(config));
    const QString rsi = QStringLiteral("rsi:") + config;
    // A KUKA model with an xMate's address, an xMate model with an RSI config.
    const Run kuka_address = runStudio({"--model", "kr6_r900_sixx", "--robot", "10.0.0.1:1337"});
    QCOMPARE(kuka_address.code, 2);
    QVERIFY2(kuka_address.err.contains("kr6_r900_sixx is a KUKA") && kuka_address.err.contains("--robot rsi:"),
             qPrintable(kuka_address.err));
    const Run xmate_rsi = runStudio({"--model", "xmate7_pro", "--robot", rsi});
    QCOMPARE(xmate_rsi.code, 2);
    QVERIFY2(xmate_rsi.err.contains("xmate7_pro is an xMate") && xmate_rsi.err.contains("--robot HOST:PORT"),
             qPrintable(xmate_rsi.err));
    const Run no_model = runStudio({"--robot", rsi});
    QCOMPARE(no_model.code, 2);
    QVERIFY2(no_model.err.contains("add --model kr6_r900_sixx or --model kr16_2"), qPrintable(no_model.err));
    // The files: missing, not an Ethernet config, and two contexts that use it.
    const Run missing = runStudio({"--robot", "rsi:/nowhere/RSI_EthernetConfig.xml", "--model", "kr16_2"});
    QCOMPARE(missing.code, 2);
    QVERIFY2(missing.err.contains("\"/nowhere/RSI_EthernetConfig.xml\" does not exist"), qPrintable(missing.err));
    const QString context = QFileInfo(config).absolutePath() + QStringLiteral("/rci_replay.rsi.xml");
    const Run not_config = runStudio({"--robot", QStringLiteral("rsi:") + context, "--model", "kr16_2"});
    QCOMPARE(not_config.code, 2);
    QVERIFY2(not_config.err.contains("cannot be used") && not_config.err.contains("rci_replay.rsi.xml:"),
             qPrintable(not_config.err));
    const Run which = runStudio({"--robot", rsi, "--model", "kr16_2"});
    QCOMPARE(which.code, 2);
    QVERIFY2(which.err.contains("--context NAME.rsi.xml") && which.err.contains("rci_replay.rsi.xml"),
             qPrintable(which.err));
    const Run bad_context = runStudio({"--robot", rsi, "--model", "kr16_2", "--context", config});
    QCOMPARE(bad_context.code, 2);
    QVERIFY2(bad_context.err.contains("the RSI context cannot be used"), qPrintable(bad_context.err));
    // Options that belong to a KUKA over RSI only; the sensor's address.
    const Run sensor_sim = runStudio({"--model", "kr6_r900_sixx", "--ft-sensor", "192.168.1.1"});
    QCOMPARE(sensor_sim.code, 2);
    QVERIFY2(sensor_sim.err.contains("--ft-sensor is for a KUKA over RSI"), qPrintable(sensor_sim.err));
    const Run bad_sensor =
        runStudio({"--robot", rsi, "--model", "kr16_2", "--context", context, "--ft-sensor", "192.168.1.1:0"});
    QCOMPARE(bad_sensor.code, 2);
    QVERIFY2(bad_sensor.err.contains("is not a port of the F/T sensor"), qPrintable(bad_sensor.err));
    const Run lockstep = runStudio({"--model", "kr16_2", "--lockstep"});
    QCOMPARE(lockstep.code, 2);
    QVERIFY2(lockstep.err.contains("leave out --lockstep"), qPrintable(lockstep.err));
    const Run screenshot = runStudio({"--screenshot", "x.png", "--robot", rsi, "--model", "kr16_2", "--context", context});
    QCOMPARE(screenshot.code, 2);
    QVERIFY2(screenshot.err.contains("leave out --robot"), qPrintable(screenshot.err));
    const Run unknown = runStudio({"--model", "kr210"});
    QCOMPARE(unknown.code, 2);
    QVERIFY2(unknown.err.contains("kr6_r900_sixx or kr16_2"), qPrintable(unknown.err));
  }
  void screenshotOfTheKukaSimulator() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("kuka.png");
    const Run run = runStudio({"--model", "kr6_r900_sixx", "--screenshot", path});
    QVERIFY2(run.code == 0, qPrintable(run.err));
    QVERIFY2(!run.out.contains("placeholder"), qPrintable(run.out));
    QImage image(path);
    QVERIFY(!image.isNull());
    const QRect view(image.width() * 3 / 10, image.height() / 10, image.width() * 4 / 10, image.height() * 4 / 10);
    QVERIFY2(distinctColours(image, view) > 20, "the 3D view area looks empty");
  }
  void screenshotShowsTheWindowAndRobot() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("window.png");
    const Run run = runStudio({"--lockstep", "--screenshot", path});
    QVERIFY2(run.code == 0, qPrintable(run.err));
    QVERIFY2(!run.out.contains("placeholder"), qPrintable(run.out));  // the 3D view was captured
    QImage image(path);
    QVERIFY(!image.isNull());
    QVERIFY(image.width() >= 1200 && image.height() >= 800);
    // The 3D view sits in the upper middle of the default layout: a rendered robot on a grid.
    const QRect view(image.width() * 3 / 10, image.height() / 10, image.width() * 4 / 10, image.height() * 4 / 10);
    QVERIFY2(distinctColours(image, view) > 20, "the 3D view area looks empty");
  }
};

QTEST_MAIN(TestStudioApp)
#include "test_studio_app.moc"
