// SPDX-License-Identifier: Apache-2.0
// test_studio_app (under xvfb-run): runs the rci-studio program -- its option handling, and
// --screenshot rendering the whole window with the 3D view to a PNG.
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
