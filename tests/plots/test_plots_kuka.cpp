// SPDX-License-Identifier: Apache-2.0
// Tests of ui/plots on a KUKA: the signal set from the arm's capabilities, synthetic arm samples into
// series (velocity by differences, sensor wrench, late answers), units, CSV columns and rows, a ring
// of ~60 s at 250 Hz and 83 Hz, and the plots of a real session on the built-in KUKA simulator.
#include <QCheckBox>
#include <QFile>
#include <QLabel>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <memory>
#include <vector>

#include "../gui/gui_test_support.h"
#include "model/robot_spec.h"
#include "plots/csv_export.h"
#include "plots/plot_setup.h"
#include "plots/plots_widget.h"
#include "session/session.h"
#include "window/parts.h"

using namespace rci::ui::plots;
using xmate::arm::ArmSample;
using xmate::arm::Capability;

namespace {

const xmate::model::RobotSpec& kr6() {
  const xmate::model::RobotSpec* spec = xmate::model::findRobotSpec("kr6_r900_sixx");
  Q_ASSERT(spec != nullptr);
  return *spec;
}

PlotSetup fullKuka(double cycle_s = 0.004) {
  return armSetup(kr6(), Capability::kGearTorques | Capability::kMotorCurrents | Capability::kTcpSetPoint, cycle_s,
                  true, true);
}

PlotSetup bareKuka() { return armSetup(kr6(), 0, 0.004, false, false); }

// Cycle k (1-based) of one RSI session: axis j moves at 0.1 * (j + 1) rad/s; the set-point leads by
// 0.01 rad; gear torque j + 1 Nm; motor current 0.5 * (j + 1) A. The arrival time jitters by up to
// +-1.5 ms around the cycle's nominal time, as a PC's clock sees RSI packets.
ArmSample cycleSample(uint64_t k, double cycle_s = 0.004, uint32_t session = 1) {
  ArmSample s;
  s.cycle = k;
  s.session = session;
  const double t = double(k) * cycle_s;
  s.time = t + ((k % 3 == 0) ? 0.0015 : (k % 3 == 1) ? -0.0015 : 0.0);
  for (int j = 0; j < 6; ++j) {
    s.q[size_t(j)] = 0.1 * (j + 1) * t;
    s.q_command[size_t(j)] = s.q[size_t(j)] + 0.01;
    s.gear_torque[size_t(j)] = j + 1;
    s.motor_current[size_t(j)] = 0.5 * (j + 1);
  }
  s.tcp_position = {0.4 + 0.1 * t, 0.2, 0.6};
  s.tcp_position_command = {0.41 + 0.1 * t, 0.2, 0.6};
  return s;
}

std::vector<ArmSample> cycles(uint64_t first, int count, double cycle_s = 0.004) {
  std::vector<ArmSample> samples;
  for (int i = 0; i < count; ++i) samples.push_back(cycleSample(first + uint64_t(i), cycle_s));
  return samples;
}

ArmExtras sensorExtras() {
  ArmExtras extras;
  extras.force_valid = true;
  extras.force = {1, 2, 3, 0.1, 0.2, 0.3};
  extras.late_answers = 3;
  return extras;
}

// Feeds samples in display-tick batches (8 cycles of 4 ms ~ 33 ms).
void feed(PlotsWidget& widget, const std::vector<ArmSample>& samples, const ArmExtras& extras = {}) {
  for (size_t i = 0; i < samples.size(); i += 8)
    widget.addArmSamples(samples.data() + i, int(std::min<size_t>(8, samples.size() - i)), extras);
}

// The chooser's box with this text that the operator can see (nullptr if none): a box of a signal
// or joint the arm does not have is hidden.
QCheckBox* boxNamed(QWidget& widget, const QString& text) {
  for (QCheckBox* box : widget.findChildren<QCheckBox*>())
    if (box->text() == text && box->isVisibleTo(&widget)) return box;
  return nullptr;
}

QList<QByteArray> csvLines(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? file.readAll().split('\n') : QList<QByteArray>();
}

QByteArray joined(const QStringList& columns) { return columns.join(QLatin1Char(',')).toLatin1(); }

QStringList axisColumns(const QString& key, const QString& unit) {
  QStringList columns;
  for (int a = 1; a <= 6; ++a) columns << QStringLiteral("%1_A%2_%3").arg(key).arg(a).arg(unit);
  return columns;
}

}  // namespace

class TestPlotsKuka : public QObject {
  Q_OBJECT
 private slots:
  void unitsAndNames();
  void setupFollowsCapabilities();
  void missingCapabilitiesHideSignals();
  void armSamplesFillSeries();
  void velocityRestartsWithSession();
  void ringHoldsAMinuteAtKukaRates_data();
  void ringHoldsAMinuteAtKukaRates();
  void csvNamesKukaColumns();
  void frozenViewExportHasShownKukaSeries();
  void xmateWidgetIgnoresArmSamples();
  void plotsOfKukaSimulatorSession();
};

void TestPlotsKuka::unitsAndNames() {
  QCOMPARE(quantityUnit(Quantity::kMotorCurrent), QString("A"));
  QCOMPARE(quantityTitle(Quantity::kMotorCurrent), QString("Motor current"));
  QCOMPARE(quantityOf(Signal::kMotorCurrent), Quantity::kMotorCurrent);
  QCOMPARE(quantityOf(Signal::kGearTorque), Quantity::kTorque);
  QCOMPARE(quantityOf(Signal::kAxisSetPoint), Quantity::kPosition);
  QCOMPARE(quantityOf(Signal::kAxisVelocity), Quantity::kVelocity);
  QCOMPARE(quantityOf(Signal::kSensorTorque), Quantity::kForce);
  QCOMPARE(quantityOf(Signal::kLateAnswers), Quantity::kDelay);
  QCOMPARE(signalUnit(Signal::kSensorForce), QString("N"));
  QCOMPARE(signalUnit(Signal::kSensorTorque), QString("Nm"));
  QCOMPARE(signalUnit(Signal::kGearTorque), QString("Nm"));
  QCOMPARE(signalUnit(Signal::kAxisVelocity), QString("rad/s"));
  QCOMPARE(csvColumnName(channelOf(Signal::kAxisActual, 0), "A"), QString("q_A1_rad"));
  QCOMPARE(csvColumnName(channelOf(Signal::kAxisSetPoint, 5), "A"), QString("q_set_A6_rad"));
  QCOMPARE(csvColumnName(channelOf(Signal::kAxisVelocity, 2), "A"), QString("dq_A3_rad_per_s"));
  QCOMPARE(csvColumnName(channelOf(Signal::kMotorCurrent, 3), "A"), QString("current_A4_A"));
  QCOMPARE(csvColumnName(channelOf(Signal::kSensorTorque, 2), "A"), QString("ft_Tz_Nm"));
  QCOMPARE(csvColumnName(channelOf(Signal::kLateAnswers, 0), "A"), QString("rsi_late_answers"));
  QCOMPARE(csvColumnName(channelOf(Signal::kTorqueExternal, 6)), QString("tau_ext_J7_Nm"));  // the xMate's stay
}

void TestPlotsKuka::setupFollowsCapabilities() {
  const PlotSetup full = fullKuka();
  QCOMPARE(full.source, PlotSetup::Source::kArmSamples);
  QCOMPARE(full.joints, 6);
  QCOMPARE(full.joint_prefix, QString("A"));
  QCOMPARE(full.sample_rate_hz, 250.0);
  for (Signal s : {Signal::kAxisActual, Signal::kAxisSetPoint, Signal::kAxisVelocity, Signal::kGearTorque,
                   Signal::kMotorCurrent, Signal::kSensorForce, Signal::kSensorTorque, Signal::kLateAnswers})
    QVERIFY(full.offers(s));
  QVERIFY(!full.offers(Signal::kTorqueMeasured));
  QVERIFY(!full.offers(Signal::kPositionMeasured));
  const PlotSetup bare = bareKuka();
  // Every arm reports its TCP; the set-point only with kTcpSetPoint.
  QCOMPARE(bare.offered, (std::vector<Signal>{Signal::kAxisActual, Signal::kAxisSetPoint, Signal::kAxisVelocity,
                                              Signal::kTcpActual}));
  QVERIFY(full.offers(Signal::kTcpSetPoint));
  QVERIFY(std::abs(armSetup(kr6(), 0, 0.012, false, false).sample_rate_hz - 83.333) < 0.001);
}

void TestPlotsKuka::missingCapabilitiesHideSignals() {
  PlotsWidget widget;
  widget.resize(1200, 600);
  widget.configure(bareKuka());
  widget.show();
  QVERIFY(QTest::qWaitForWindowExposed(&widget));
  // The chooser: A1..A6, no A7, no J*; only the signals the arm has.
  for (int a = 1; a <= 6; ++a) QVERIFY2(boxNamed(widget, QStringLiteral("A%1").arg(a)) != nullptr, qPrintable(QString::number(a)));
  QVERIFY(boxNamed(widget, "A7") == nullptr);
  QVERIFY(boxNamed(widget, "J1") == nullptr);
  bool axes_caption = false;
  for (QLabel* label : widget.findChildren<QLabel*>()) axes_caption = axes_caption || label->text() == "Axes";
  QVERIFY(axes_caption);
  for (const char* offered : {"q", "q set", "dq"}) QVERIFY2(boxNamed(widget, offered) != nullptr, offered);
  for (const char* missing : {"τ gear", "I motor", "F sensor", "T sensor", "late", "τ", "τ cmd", "τ ext"})
    QVERIFY2(boxNamed(widget, QString::fromUtf8(missing)) == nullptr, missing);
  // The charts: position and velocity only.
  QVERIFY(widget.isChartShown(Quantity::kPosition) && widget.canvas(Quantity::kPosition).widget()->isVisible());
  QVERIFY(widget.isChartShown(Quantity::kVelocity));
  for (Quantity q : {Quantity::kTorque, Quantity::kMotorCurrent, Quantity::kForce, Quantity::kDelay}) {
    QVERIFY(!widget.isChartShown(q));
    QVERIFY(!widget.canvas(q).widget()->isVisible());
  }
  // Ticking a signal the arm does not have changes nothing.
  widget.setSignalVisible(Signal::kGearTorque, true);
  QVERIFY(!widget.isSignalVisible(Signal::kGearTorque));
  QVERIFY(!widget.isChartShown(Quantity::kTorque));
  feed(widget, cycles(1, 100));
  widget.redrawNow();
  QCOMPARE(widget.visibleSeriesCount(), 12);  // actual and velocity of 6 axes
  // The ring keeps only the signals offered.
  QVERIFY(widget.buffer().keeps(channelOf(Signal::kAxisActual, 0)));
  QVERIFY(!widget.buffer().keeps(channelOf(Signal::kGearTorque, 0)));
  QVERIFY(std::isnan(widget.buffer().value(channelOf(Signal::kGearTorque, 0), 0)));
}

void TestPlotsKuka::armSamplesFillSeries() {
  PlotsWidget widget;
  widget.resize(1200, 800);
  widget.configure(fullKuka());
  widget.show();
  QVERIFY(QTest::qWaitForWindowExposed(&widget));
  // Charts of the arm's signals; the sensor and late-answer charts wait until ticked.
  QVERIFY(widget.isChartShown(Quantity::kTorque));
  QVERIFY(widget.isChartShown(Quantity::kMotorCurrent));
  QVERIFY(!widget.isChartShown(Quantity::kForce));
  QVERIFY(!widget.isChartShown(Quantity::kDelay));
  QVERIFY(boxNamed(widget, "F sensor") != nullptr);
  QVERIFY(!boxNamed(widget, "F sensor")->isChecked());

  const std::vector<ArmSample> samples = cycles(1, 1000);  // 4 s
  feed(widget, samples, sensorExtras());
  const PlotBuffer& buffer = widget.buffer();
  QCOMPARE(buffer.size(), 1000);
  QCOMPARE(buffer.newestTime(), samples.back().time);
  for (int j = 0; j < 6; ++j) {
    QCOMPARE(buffer.value(channelOf(Signal::kAxisActual, j), 500), samples[500].q[size_t(j)]);
    QCOMPARE(buffer.value(channelOf(Signal::kAxisSetPoint, j), 500), samples[500].q_command[size_t(j)]);
    QCOMPARE(buffer.value(channelOf(Signal::kGearTorque, j), 500), j + 1.0);
    QCOMPARE(buffer.value(channelOf(Signal::kMotorCurrent, j), 500), 0.5 * (j + 1));
    // Velocity by differences over the cycle time, whatever the arrival jitter; none for the first sample.
    QVERIFY(std::isnan(buffer.value(channelOf(Signal::kAxisVelocity, j), 0)));
    for (int i : {1, 2, 3, 500, 999})
      QVERIFY2(std::abs(buffer.value(channelOf(Signal::kAxisVelocity, j), i) - 0.1 * (j + 1)) < 1e-9,
               qPrintable(QStringLiteral("A%1 sample %2: %3").arg(j + 1).arg(i).arg(
                   buffer.value(channelOf(Signal::kAxisVelocity, j), i))));
  }
  QCOMPARE(buffer.value(channelOf(Signal::kSensorForce, 2), 10), 3.0);
  QCOMPARE(buffer.value(channelOf(Signal::kSensorTorque, 0), 10), 0.1);
  QCOMPARE(buffer.value(channelOf(Signal::kLateAnswers, 0), 10), 3.0);

  widget.redrawNow();
  // Default: actual position, velocity, gear torque and motor current of A1..A6.
  QCOMPARE(widget.visibleSeriesCount(), 24);
  for (int j = 0; j < 6; ++j) {
    for (Signal s : {Signal::kAxisActual, Signal::kAxisVelocity, Signal::kGearTorque, Signal::kMotorCurrent}) {
      const QList<QPointF> points = widget.canvas(quantityOf(s)).seriesPoints(channelOf(s, j));
      QVERIFY(!points.isEmpty());
      QCOMPARE(points.last().x(), 0.0);  // the newest sample at the right edge
    }
  }
  QVERIFY(widget.canvas(Quantity::kPosition).seriesPoints(channelOf(Signal::kAxisActual, 6)).isEmpty());  // no A7
  QCOMPARE(widget.canvas(Quantity::kMotorCurrent).seriesPoints(channelOf(Signal::kMotorCurrent, 2)).last().y(), 1.5);

  // The operator ticks the sensor's force and the late answers: their charts appear with 3 and 1 lines.
  boxNamed(widget, "F sensor")->click();
  QVERIFY(widget.isChartShown(Quantity::kForce));
  QVERIFY(widget.canvas(Quantity::kForce).widget()->isVisible());
  widget.setSignalVisible(Signal::kLateAnswers, true);
  QVERIFY(widget.canvas(Quantity::kDelay).widget()->isVisible());
  QCOMPARE(widget.visibleSeriesCount(), 24 + 3 + 1);
  QCOMPARE(widget.canvas(Quantity::kForce).seriesPoints(channelOf(Signal::kSensorForce, 1)).last().y(), 2.0);
  QCOMPARE(widget.canvas(Quantity::kDelay).seriesPoints(channelOf(Signal::kLateAnswers, 0)).last().y(), 3.0);
  // The joint chooser leaves the sensor's lines alone; it hides an axis everywhere.
  boxNamed(widget, "A2")->click();
  QCOMPARE(widget.visibleSeriesCount(), 28 - 4);
  QVERIFY(widget.canvas(Quantity::kForce).isSeriesVisible(channelOf(Signal::kSensorForce, 1)));
  // Unticking the force again takes its chart away.
  widget.setSignalVisible(Signal::kSensorForce, false);
  QVERIFY(!widget.isChartShown(Quantity::kForce));
  // Without a healthy sensor reading the force has gaps (NaN), not zeros.
  std::vector<ArmSample> more = cycles(1001, 8);
  feed(widget, more, ArmExtras{});
  QVERIFY(std::isnan(buffer.value(channelOf(Signal::kSensorForce, 0), buffer.size() - 1)));
}

void TestPlotsKuka::velocityRestartsWithSession() {
  PlotsWidget widget;
  widget.configure(fullKuka());
  std::vector<ArmSample> samples = cycles(1, 10);
  // RSI started again: a new session counts cycles from 1, its axes elsewhere.
  ArmSample restart = cycleSample(1, 0.004, 2);
  restart.time = samples.back().time + 0.5;
  restart.q.fill(2.0);
  samples.push_back(restart);
  ArmSample next = restart;
  next.cycle = 2;
  next.time += 0.004;
  next.q.fill(2.0 + 0.004 * 0.5);
  samples.push_back(next);
  widget.addArmSamples(samples.data(), int(samples.size()), {});
  const PlotBuffer& buffer = widget.buffer();
  QCOMPARE(buffer.size(), 12);
  QVERIFY(std::isnan(buffer.value(channelOf(Signal::kAxisVelocity, 0), 10)));  // no jump across the restart
  QVERIFY(std::abs(buffer.value(channelOf(Signal::kAxisVelocity, 0), 11) - 0.5) < 1e-9);
  // clear() forgets the previous sample too.
  widget.clear();
  widget.addArmSamples(&next, 1, {});
  QVERIFY(std::isnan(buffer.value(channelOf(Signal::kAxisVelocity, 0), 0)));
}

void TestPlotsKuka::ringHoldsAMinuteAtKukaRates_data() {
  QTest::addColumn<double>("cycle_s");
  QTest::newRow("4 ms") << 0.004;
  QTest::newRow("12 ms") << 0.012;
}

void TestPlotsKuka::ringHoldsAMinuteAtKukaRates() {
  QFETCH(double, cycle_s);
  PlotsWidget widget;
  widget.resize(900, 700);
  widget.configure(fullKuka(cycle_s));
  widget.show();
  QVERIFY(QTest::qWaitForWindowExposed(&widget));
  const int count = int(std::lround(70.0 / cycle_s));  // 70 s of cycles
  feed(widget, cycles(1, count, cycle_s));
  const PlotBuffer& buffer = widget.buffer();
  QVERIFY(buffer.size() < count);  // it wrapped...
  const double held = buffer.newestTime() - buffer.oldestTime();
  QVERIFY2(held >= 60.0 && held <= PlotsWidget::kBufferSeconds + 0.1, qPrintable(QString::number(held)));  // ...keeping ~60 s
  // Decimation per pixel column: a 60 s window of the position chart has at most 2 points a column.
  widget.setWindowSeconds(60);
  widget.redrawNow();
  const int columns = widget.canvas(Quantity::kPosition).plotWidth();
  const QList<QPointF> points = widget.canvas(Quantity::kPosition).seriesPoints(channelOf(Signal::kAxisActual, 0));
  QVERIFY(points.size() >= 2);
  QVERIFY2(points.size() <= 2 * columns + 2, qPrintable(QStringLiteral("%1 points, %2 columns").arg(points.size()).arg(columns)));
  QVERIFY(points.first().x() >= -60.0 - 1e-9);
  // The line is a ramp: its ends are the window's ends.
  QVERIFY(std::abs(points.last().y() - 0.1 * double(count) * cycle_s) < 1e-9);
}

void TestPlotsKuka::csvNamesKukaColumns() {
  PlotsWidget widget;
  widget.configure(fullKuka());
  feed(widget, cycles(1, 3), sensorExtras());
  QTemporaryDir dir;
  QString error;
  const QString path = dir.filePath("kuka.csv");
  QVERIFY2(widget.exportCsv(path, PlotsWidget::ExportScope::kWholeBuffer, &error), qPrintable(error));
  const QList<QByteArray> lines = csvLines(path);
  const QStringList header = QStringList{"time_s"} + axisColumns("q", "rad") + axisColumns("q_set", "rad") +
                             axisColumns("dq", "rad_per_s") + axisColumns("tau_gear", "Nm") +
                             axisColumns("current", "A") +
                             QStringList{"ft_Fx_N", "ft_Fy_N", "ft_Fz_N", "ft_Tx_Nm", "ft_Ty_Nm", "ft_Tz_Nm",
                                         "rsi_late_answers", "tcp_X_m", "tcp_Y_m", "tcp_Z_m", "tcp_set_X_m",
                                         "tcp_set_Y_m", "tcp_set_Z_m"};
  QCOMPARE(lines[0], joined(header));
  QCOMPARE(lines.size(), 3 + 2);  // header, 3 rows, trailing empty piece
  const QList<QByteArray> first = lines[1].split(',');
  QCOMPARE(first.size(), header.size());
  QCOMPARE(first[0].toDouble(), cycleSample(1).time);
  QCOMPARE(first[1 + 12], QByteArray());  // the first velocity is not known: an empty field
  QCOMPARE(first[header.indexOf("tcp_X_m")].toDouble(), cycleSample(1).tcp_position[0]);
  QCOMPARE(first[header.indexOf("tcp_set_X_m")].toDouble(), cycleSample(1).tcp_position_command[0]);
  const QList<QByteArray> second = lines[2].split(',');
  QVERIFY(std::abs(second[1 + 12].toDouble() - 0.1) < 1e-9);  // dq A1
  QCOMPARE(second[1 + 18 + 5].toDouble(), 6.0);                // tau_gear A6
  QCOMPARE(second[1 + 24 + 1].toDouble(), 1.0);                // current A2
  QCOMPARE(second[1 + 30 + 2].toDouble(), 3.0);                // Fz
  QCOMPARE(second[1 + 36].toDouble(), 3.0);                    // late answers

  // An arm without gear torques, currents, sensor, RSI count or TCP set-point: only its own columns.
  PlotsWidget bare;
  bare.configure(bareKuka());
  feed(bare, cycles(1, 2));
  QVERIFY2(bare.exportCsv(path, PlotsWidget::ExportScope::kWholeBuffer, &error), qPrintable(error));
  QCOMPARE(csvLines(path)[0],
           joined(QStringList{"time_s"} + axisColumns("q", "rad") + axisColumns("q_set", "rad") +
                  axisColumns("dq", "rad_per_s") + QStringList{"tcp_X_m", "tcp_Y_m", "tcp_Z_m"}));
}

void TestPlotsKuka::frozenViewExportHasShownKukaSeries() {
  PlotsWidget widget;
  widget.configure(fullKuka());
  widget.setWindowSeconds(2);
  feed(widget, cycles(1, 1250), sensorExtras());  // 5 s
  widget.setSignalVisible(Signal::kSensorForce, true);
  widget.setJointVisible(3, false);  // A4 off
  widget.setFrozen(true);
  QTemporaryDir dir;
  QString error;
  const QString path = dir.filePath("view.csv");
  QVERIFY2(widget.exportCsv(path, PlotsWidget::ExportScope::kFrozenView, &error), qPrintable(error));
  const QList<QByteArray> lines = csvLines(path);
  const QList<QByteArray> header = lines[0].split(',');
  QCOMPARE(header.size(), 1 + 4 * 5 + 3);  // time, 4 signals x 5 axes, Fx Fy Fz
  QVERIFY(header.contains("q_A1_rad"));
  QVERIFY(!header.contains("q_A4_rad"));
  QVERIFY(header.contains("ft_Fy_N"));
  QVERIFY(!header.contains("ft_Tx_Nm"));
  QVERIFY(!header.contains("q_set_A1_rad"));
  // Rows of the last 2 s: ~500 at 250 Hz (arrival jitter moves the window's ends by a sample).
  QVERIFY2(std::abs(int(lines.size()) - 2 - 500) <= 2, qPrintable(QString::number(lines.size())));
  // Configuring another arm resumes the frozen view and starts an empty ring.
  QSignalSpy frozen(&widget, &PlotsWidget::frozenChanged);
  widget.configure(bareKuka());
  QVERIFY(!widget.isFrozen());
  QCOMPARE(frozen.count(), 1);
  QVERIFY(widget.buffer().empty());
}

void TestPlotsKuka::xmateWidgetIgnoresArmSamples() {
  PlotsWidget widget;
  QCOMPARE(widget.setup(), xmateSetup());
  QVERIFY(!widget.recordsArmSamples());
  const std::vector<ArmSample> samples = cycles(1, 10);
  widget.addArmSamples(samples.data(), int(samples.size()), {});
  QVERIFY(widget.buffer().empty());  // an xMate's plots come from its state samples
  widget.configure(fullKuka());
  xmate::client::StateSample state;
  widget.addSamples(&state, 1);
  QVERIFY(widget.buffer().empty());
  // Back to the xMate: its chooser, charts and ring as before.
  widget.configure(xmateSetup());
  QVERIFY(boxNamed(widget, "J7") != nullptr);
  QVERIFY(widget.isChartShown(Quantity::kTorque));
  QVERIFY(!widget.isChartShown(Quantity::kMotorCurrent));
  QVERIFY(widget.isSignalVisible(Signal::kPositionMeasured));
  QVERIFY(!widget.isSignalVisible(Signal::kAxisActual));
  QCOMPARE(widget.buffer().capacity(), int(PlotsWidget::kBufferSeconds * PlotsWidget::kSampleRateHz));
}

// The window's factory on a real session: the built-in KUKA simulator's samples reach the plots.
void TestPlotsKuka::plotsOfKukaSimulatorSession() {
  rci::ui::Session session;
  QWidget* created = rci::ui::createPlotsWidget(session, nullptr);
  std::unique_ptr<QWidget> owner(created);
  auto* plots = qobject_cast<PlotsWidget*>(created);
  QVERIFY(plots != nullptr);
  QSignalSpy opened(&session, &rci::ui::Session::opened);
  QSignalSpy failed(&session, &rci::ui::Session::openFailed);
  session.open(rci::ui::test::kukaSimulator());
  QTRY_VERIFY_WITH_TIMEOUT(opened.count() == 1 || failed.count() == 1, 15000);
  QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));

  const PlotSetup& setup = plots->setup();
  QVERIFY(plots->recordsArmSamples());
  QCOMPARE(setup.joint_prefix, QString("A"));
  QCOMPARE(plots->jointCount(), 6);
  QCOMPARE(setup.sample_rate_hz, 1.0 / session.arm()->cycleSeconds());
  const auto caps = session.arm()->capabilities();
  QCOMPARE(setup.offers(Signal::kGearTorque), xmate::arm::has(caps, Capability::kGearTorques));
  QCOMPARE(setup.offers(Signal::kMotorCurrent), xmate::arm::has(caps, Capability::kMotorCurrents));
  QCOMPARE(setup.offers(Signal::kSensorForce), session.live().has_force_sensor);
  QVERIFY(setup.offers(Signal::kLateAnswers));
  for (int a = 1; a <= 6; ++a) QVERIFY(boxNamed(*plots, QStringLiteral("A%1").arg(a)) != nullptr);

  // Samples of A1..A6 arrive: finite actual positions and set-points, and velocities after the first.
  const PlotBuffer& buffer = plots->buffer();
  auto axesRecorded = [&] {
    if (buffer.size() < 50) return false;
    const int last = buffer.size() - 1;
    for (int j = 0; j < 6; ++j)
      if (!std::isfinite(buffer.value(channelOf(Signal::kAxisActual, j), last)) ||
          !std::isfinite(buffer.value(channelOf(Signal::kAxisSetPoint, j), last)) ||
          !std::isfinite(buffer.value(channelOf(Signal::kAxisVelocity, j), last)))
        return false;
    return true;
  };
  QTRY_VERIFY_WITH_TIMEOUT(axesRecorded(), 15000);
  QVERIFY(buffer.newestTime() > buffer.oldestTime());
  // Some axis stands away from zero (the simulator's start pose), so the values are the arm's.
  double largest = 0;
  for (int j = 0; j < 6; ++j) largest = std::max(largest, std::abs(buffer.value(channelOf(Signal::kAxisActual, j), 0)));
  QVERIFY(largest > 0.01);
  if (setup.offers(Signal::kSensorForce))  // the simulated sensor's readings are recorded too
    QTRY_VERIFY_WITH_TIMEOUT(std::isfinite(buffer.value(channelOf(Signal::kSensorForce, 2), buffer.size() - 1)), 15000);

  // The charts draw them.
  plots->resize(1000, 700);
  plots->show();
  QVERIFY(QTest::qWaitForWindowExposed(plots));
  plots->redrawNow();
  for (int j = 0; j < 6; ++j)
    QVERIFY(!plots->canvas(Quantity::kPosition).seriesPoints(channelOf(Signal::kAxisActual, j)).isEmpty());
  session.close();
}

QTEST_MAIN(TestPlotsKuka)
#include "test_plots_kuka.moc"
