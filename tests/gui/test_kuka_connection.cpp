// SPDX-License-Identifier: Apache-2.0
// test_kuka_connection: the connection toolbar's four kinds and the targets they yield (a good and
// a refused RSI Ethernet config), the last target saved and read back with the KUKA kinds, and the
// status bar's RSI fields on the built-in KUKA simulator through a pause and an RSITimeout.
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include "gui_test_support.h"
#include "session/session.h"
#include "sim/krc_server.h"
#include "window/connection_bar.h"
#include "window/status_strip.h"
#include "window/target_settings.h"

using rci::ui::ConnectionBar;
using rci::ui::Session;
using rci::ui::SessionTarget;
using rci::ui::StatusStrip;

namespace {

constexpr int kWaitMs = 20000;

QString goodConfig() {
  return QDir(qEnvironmentVariable("RCI_DATA_DIR", QStringLiteral("."))).filePath(QStringLiteral("resources/rsi/RSI_EthernetConfig.xml"));
}

}  // namespace

class TestKukaConnection : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;

  template <typename T>
  static T* child(QObject& parent, const char* name) {
    T* found = parent.findChild<T*>(QString::fromLatin1(name));
    if (found == nullptr) qFatal("no widget %s", name);
    return found;
  }

  // The Ethernet config sample with one line replaced: a config the bar must refuse.
  QString brokenConfig(const QString& from, const QString& to) {
    QFile in(goodConfig());
    if (!in.open(QIODevice::ReadOnly)) return QString();
    QString text = QString::fromUtf8(in.readAll());
    text.replace(from, to);
    const QString path = dir_.filePath(QStringLiteral("broken.xml"));
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate)) return QString();
    out.write(text.toUtf8());
    return path;
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QVERIFY(dir_.isValid());
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir_.filePath(QStringLiteral("config")));
    QSettings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio")).clear();
    QVERIFY2(QFile::exists(goodConfig()), qPrintable(goodConfig()));
  }

  void eachKindYieldsItsTarget() {
    ConnectionBar bar;
    bar.resize(1366, bar.sizeHint().height());  // as wide as a small screen: no widget overflows
    bar.show();
    // The toolbar shows and hides its widgets when it lays them out.
    const auto shown = [&bar](QWidget* widget) {
      bar.layout()->activate();
      QApplication::processEvents();
      return widget->isVisible();
    };
    auto* kind = child<QComboBox>(bar, "connection.kind");
    auto* model = child<QComboBox>(bar, "connection.model");
    auto* config = child<QComboBox>(bar, "connection.rsiConfig");
    auto* sensor = child<QLineEdit>(bar, "connection.ftSensor");
    auto* robot = child<QComboBox>(bar, "connection.robot");
    QCOMPARE(kind->count(), 4);
    SessionTarget target;
    QString error;

    // The built-in xMate simulator, the default: xMate7 Pro of the four xMates.
    QCOMPARE(kind->currentIndex(), 0);
    QCOMPARE(model->count(), 4);
    QCOMPARE(model->currentText(), QStringLiteral("xMate7 Pro"));
    QVERIFY(!shown(config));
    QVERIFY(!shown(robot));
    model->setCurrentIndex(model->findData(QStringLiteral("xmate3")));
    QVERIFY(bar.currentTarget(target, error));
    QCOMPARE(target.kind, SessionTarget::Kind::kSimulator);
    QCOMPARE(target.type, xmate::XMATE3);

    // An xMate robot at HOST:PORT.
    kind->setCurrentIndex(1);
    QVERIFY(shown(robot));
    robot->setEditText(QStringLiteral("10.0.0.7:1338"));
    QVERIFY(bar.currentTarget(target, error));
    QCOMPARE(target.kind, SessionTarget::Kind::kRobot);
    QCOMPARE(target.host, QStringLiteral("10.0.0.7"));
    QCOMPARE(target.port, quint16(1338));

    // The built-in KUKA simulator: the two KUKA arms only.
    kind->setCurrentIndex(2);
    QVERIFY(!shown(robot));
    QVERIFY(!shown(config));
    QCOMPARE(model->count(), 2);
    QCOMPARE(model->itemText(0), QStringLiteral("KR 6 R900 sixx"));
    QCOMPARE(model->itemText(1), QStringLiteral("KR 16-2"));
    QVERIFY(bar.currentTarget(target, error));
    QCOMPARE(target.kind, SessionTarget::Kind::kKukaSimulator);
    QCOMPARE(target.kuka_model, QStringLiteral("kr6_r900_sixx"));
    model->setCurrentIndex(1);
    QVERIFY(bar.currentTarget(target, error));
    QCOMPARE(target.kuka_model, QStringLiteral("kr16_2"));
    QVERIFY(target.isKuka());

    // Back on an xMate kind, the xMate chosen before is still chosen.
    kind->setCurrentIndex(0);
    QCOMPARE(model->count(), 4);
    QCOMPARE(model->currentData().toString(), QStringLiteral("xmate3"));

    // A KUKA over RSI: no file yet, refused with what to do.
    kind->setCurrentIndex(3);
    QCOMPARE(model->currentData().toString(), QStringLiteral("kr16_2"));
    QVERIFY(shown(config));
    QVERIFY(shown(sensor));
    QVERIFY(shown(child<QToolButton>(bar, "connection.rsiBrowse")));
    config->setEditText(QString());
    QVERIFY(!bar.currentTarget(target, error));
    QVERIFY2(error.contains(QStringLiteral("Ethernet config")), qPrintable(error));

    // The sample config: the listen address beside it, and the target.
    config->setEditText(goodConfig());
    auto* listen = child<QLabel>(bar, "connection.rsiListen");
    QCOMPARE(listen->text(), QStringLiteral("listens on 192.168.1.20:49152"));
    QVERIFY(bar.currentTarget(target, error));
    QCOMPARE(target.kind, SessionTarget::Kind::kKukaRobot);
    QCOMPARE(target.kuka_model, QStringLiteral("kr16_2"));
    QCOMPARE(target.rsi_config, QFileInfo(goodConfig()).absoluteFilePath());
    QCOMPARE(target.ft_sensor, QString());
    // Two sample contexts beside it use it: the operator chooses the one the robot runs.
    auto* context = child<QComboBox>(bar, "connection.rsiContext");
    QVERIFY(shown(context));
    QCOMPARE(context->count(), 2);
    context->setCurrentIndex(context->findText(QStringLiteral("rci_replay")));
    QVERIFY(bar.currentTarget(target, error));
    QCOMPARE(QFileInfo(target.rsi_context).fileName(), QStringLiteral("rci_replay.rsi.xml"));
    sensor->setText(QStringLiteral("192.168.1.1"));
    QVERIFY(bar.currentTarget(target, error));
    QCOMPARE(target.ft_sensor, QStringLiteral("192.168.1.1"));
    sensor->setText(QStringLiteral("192.168.1.1:49153"));
    QVERIFY(bar.currentTarget(target, error));
    QCOMPARE(target.ft_sensor, QStringLiteral("192.168.1.1:49153"));
    sensor->setText(QStringLiteral("192.168.1.1:70000"));
    QVERIFY(!bar.currentTarget(target, error));
    QVERIFY2(error.contains(QStringLiteral("\"70000\" is not a port")), qPrintable(error));
    sensor->clear();

    // With every field of this kind shown, the bar still fits a 1366 px screen.
    sensor->setText(QStringLiteral("192.168.100.200:49152"));
    QVERIFY2(bar.sizeHint().width() <= 1366, qPrintable(QString::number(bar.sizeHint().width())));
    sensor->clear();

    // A missing file and a broken one: refused with what is wrong, through Connect too.
    QSignalSpy refused(&bar, &ConnectionBar::inputRefused);
    QSignalSpy requested(&bar, &ConnectionBar::connectRequested);
    config->setEditText(dir_.filePath(QStringLiteral("nowhere.xml")));
    QCOMPARE(listen->text(), QStringLiteral("file not usable"));
    QVERIFY(!bar.currentTarget(target, error));
    QVERIFY2(error.contains(QStringLiteral("does not exist")), qPrintable(error));
    const QString broken = brokenConfig(QStringLiteral("<PORT>49152</PORT>"), QStringLiteral("<PORT>0</PORT>"));
    QVERIFY(!broken.isEmpty());
    config->setEditText(broken);
    QCOMPARE(listen->text(), QStringLiteral("file not usable"));
    QVERIFY2(listen->toolTip().contains(QStringLiteral("PORT")), qPrintable(listen->toolTip()));
    child<QPushButton>(bar, "connection.connect")->click();
    QCOMPARE(refused.count(), 1);
    QCOMPARE(requested.count(), 0);
    const QString reason = refused.first().first().toString();
    QVERIFY2(reason.contains(QStringLiteral("broken.xml")) && reason.contains(QStringLiteral("PORT")), qPrintable(reason));
    QVERIFY2(reason.contains(QStringLiteral("cannot be used")), qPrintable(reason));
    // A good config alone in its folder: no context the robot could run uses it.
    const QString alone = dir_.filePath(QStringLiteral("RSI_EthernetConfig.xml"));
    QVERIFY(QFile::copy(goodConfig(), alone));
    config->setEditText(alone);
    QVERIFY(!shown(context));
    QVERIFY(!bar.currentTarget(target, error));
    QVERIFY2(error.contains(QStringLiteral("No RSI context")), qPrintable(error));
    config->setEditText(goodConfig());
    QCOMPARE(context->currentText(), QStringLiteral("rci_replay"));  // the choice made before
    child<QPushButton>(bar, "connection.connect")->click();
    QCOMPARE(requested.count(), 1);
    QCOMPARE(requested.first().first().value<SessionTarget>().kind, SessionTarget::Kind::kKukaRobot);
  }

  void setTargetShowsIt() {
    ConnectionBar bar;
    SessionTarget wanted;
    wanted.kind = SessionTarget::Kind::kKukaRobot;
    wanted.kuka_model = QStringLiteral("kr16_2");
    wanted.rsi_config = QFileInfo(goodConfig()).absoluteFilePath();
    wanted.ft_sensor = QStringLiteral("10.1.1.1:49152");
    wanted.rsi_context = QFileInfo(goodConfig()).absolutePath() + QStringLiteral("/rci_replay.rsi.xml");
    bar.setTarget(wanted);
    SessionTarget shown;
    QString error;
    QVERIFY2(bar.currentTarget(shown, error), qPrintable(error));
    QCOMPARE(shown.kind, wanted.kind);
    QCOMPARE(shown.kuka_model, wanted.kuka_model);
    QCOMPARE(shown.rsi_config, wanted.rsi_config);
    QCOMPARE(shown.ft_sensor, wanted.ft_sensor);
    QCOMPARE(shown.rsi_context, wanted.rsi_context);
    // The KUKA simulator of the other model: the config stays in its field for later.
    SessionTarget simulator = rci::ui::test::kukaSimulator();
    bar.setTarget(simulator);
    QVERIFY(bar.currentTarget(shown, error));
    QCOMPARE(shown.kind, SessionTarget::Kind::kKukaSimulator);
    QCOMPARE(shown.kuka_model, QStringLiteral("kr6_r900_sixx"));
    QCOMPARE(child<QComboBox>(bar, "connection.rsiConfig")->currentText(), wanted.rsi_config);
    // And an xMate again.
    SessionTarget xmate;
    xmate.type = xmate::XMATE3_PRO;
    bar.setTarget(xmate);
    QVERIFY(bar.currentTarget(shown, error));
    QCOMPARE(shown.kind, SessionTarget::Kind::kSimulator);
    QCOMPARE(shown.type, xmate::XMATE3_PRO);
  }

  void lastTargetKeepsTheKukaKinds() {
    QSettings settings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio"));
    settings.clear();
    // As saved before the KUKA kinds: read as before.
    settings.setValue(QStringLiteral("connection/kind"), QStringLiteral("robot"));
    settings.setValue(QStringLiteral("connection/model"), QStringLiteral("xmate3"));
    settings.setValue(QStringLiteral("connection/robot"), QStringLiteral("10.1.2.3:1338"));
    settings.sync();
    std::optional<SessionTarget> last = rci::ui::lastTarget();
    QVERIFY(last.has_value());
    QCOMPARE(last->kind, SessionTarget::Kind::kRobot);
    QCOMPARE(last->type, xmate::XMATE3);
    QCOMPARE(last->host, QStringLiteral("10.1.2.3"));
    QCOMPARE(last->port, quint16(1338));

    SessionTarget rsi;
    rsi.kind = SessionTarget::Kind::kKukaRobot;
    rsi.kuka_model = QStringLiteral("kr16_2");
    rsi.rsi_config = QFileInfo(goodConfig()).absoluteFilePath();
    rsi.ft_sensor = QStringLiteral("192.168.1.1");
    rsi.rsi_context = QFileInfo(goodConfig()).absolutePath() + QStringLiteral("/rci_replay.rsi.xml");
    rci::ui::saveLastTarget(rsi);
    last = rci::ui::lastTarget();
    QVERIFY(last.has_value());
    QCOMPARE(last->kind, SessionTarget::Kind::kKukaRobot);
    QCOMPARE(last->kuka_model, QStringLiteral("kr16_2"));
    QCOMPARE(last->rsi_config, rsi.rsi_config);
    QCOMPARE(last->ft_sensor, rsi.ft_sensor);
    QCOMPARE(last->rsi_context, rsi.rsi_context);
    QCOMPARE(last->type, xmate::XMATE3);  // the xMate model stays for the xMate kinds
    QCOMPARE(last->host, QStringLiteral("10.1.2.3"));
    QCOMPARE(rci::ui::recentRsiConfigs().value(0), rsi.rsi_config);

    // The KUKA simulator afterwards keeps the robot's config and sensor for the next time.
    rci::ui::saveLastTarget(rci::ui::test::kukaSimulator());
    last = rci::ui::lastTarget();
    QCOMPARE(last->kind, SessionTarget::Kind::kKukaSimulator);
    QCOMPARE(last->kuka_model, QStringLiteral("kr6_r900_sixx"));
    QCOMPARE(last->rsi_config, rsi.rsi_config);
    QCOMPARE(last->ft_sensor, rsi.ft_sensor);

    // An xMate simulator: its model; the KUKA model is kept.
    SessionTarget xmate;
    xmate.type = xmate::XMATE7;
    rci::ui::saveLastTarget(xmate);
    last = rci::ui::lastTarget();
    QCOMPARE(last->kind, SessionTarget::Kind::kSimulator);
    QCOMPARE(last->type, xmate::XMATE7);
    QCOMPARE(last->kuka_model, QStringLiteral("kr6_r900_sixx"));

    // A new bar lists the config connected with before.
    ConnectionBar bar;
    QVERIFY(child<QComboBox>(bar, "connection.rsiConfig")->findText(rsi.rsi_config) >= 0);
    settings.clear();
  }

  void statusStripFollowsRsi() {
    Session session;
    QStatusBar status;
    StatusStrip strip(session, &status);
    auto* rsi = child<QLabel>(status, "status.rsi");
    auto* cycle = child<QLabel>(status, "status.cycle");
    auto* late = child<QLabel>(status, "status.late");
    auto* sensor = child<QLabel>(status, "status.sensor");
    auto* motors = child<QLabel>(status, "status.motors");
    QVERIFY(!rsi->isVisibleTo(&status));
    QVERIFY(motors->isVisibleTo(&status));

    // Every RSI phase text the strip showed, tick by tick.
    QStringList seen;
    connect(&session, &Session::tick, &strip, [&] {
      strip.refresh();
      if (seen.isEmpty() || seen.last() != rsi->text()) seen << rsi->text();
    });
    connect(&session, &Session::opened, &strip, &StatusStrip::refresh);
    QSignalSpy failed(&session, &Session::openFailed);
    session.open(rci::ui::test::kukaSimulator());
    QTRY_VERIFY_WITH_TIMEOUT(session.isOpen() || !failed.isEmpty(), kWaitMs);
    QVERIFY2(failed.isEmpty(), qPrintable(failed.isEmpty() ? QString() : failed.first().first().toString()));

    QTRY_COMPARE_WITH_TIMEOUT(rsi->text(), QStringLiteral("RSI running"), kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(cycle->text(), QStringLiteral("Cycle 4 ms"), kWaitMs);
    QVERIFY(rsi->isVisibleTo(&status));
    QVERIFY(!motors->isVisibleTo(&status));
    QVERIFY(!child<QLabel>(status, "status.errors")->isVisibleTo(&status));
    QVERIFY(rsi->toolTip().contains(QStringLiteral("RSI running")));
    QVERIFY(child<QLabel>(status, "status.realtime")->text().startsWith(QStringLiteral("RT: ")));
    QTRY_COMPARE_WITH_TIMEOUT(sensor->text(), QStringLiteral("F/T sensor OK"), kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(child<QLabel>(status, "status.answer")->text().endsWith(QStringLiteral(" ms")), kWaitMs);
    QVERIFY(child<QLabel>(status, "status.target")->text().contains(QStringLiteral("KUKA simulator")));

    // RSI off for a while (the KRL program paused): stopped by the controller, then running again.
    xmate::sim::KrcServer* krc = session.kukaSimulator();
    QVERIFY(krc != nullptr);
    seen.clear();
    krc->krc().suspendSending(3000);
    QTRY_VERIFY_WITH_TIMEOUT(seen.contains(QStringLiteral("RSI stopped by the controller")), kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(rsi->text(), QStringLiteral("RSI running"), kWaitMs);

    // No answers: the robot counts them late, stops on its Timeout, and the simulator starts again.
    seen.clear();
    QStringList late_seen;
    connect(&session, &Session::tick, &strip, [&] { late_seen << late->text(); });
    krc->krc().dropAnswers(120);  // 100 in a row reach the Timeout; 20 more in the next session
    QTRY_VERIFY_WITH_TIMEOUT(seen.contains(QStringLiteral("RSI stopped: too many late answers")), kWaitMs);
    QVERIFY2(!late_seen.filter(QRegularExpression(QStringLiteral("^Late answers [1-9]"))).isEmpty(),
             qPrintable(late_seen.join(QStringLiteral(" | "))));
    QTRY_COMPARE_WITH_TIMEOUT(rsi->text(), QStringLiteral("RSI running"), kWaitMs);

    session.close();
    strip.refresh();
    QCOMPARE(child<QLabel>(status, "status.target")->text(), QStringLiteral("Not connected"));
    QVERIFY(!rsi->isVisibleTo(&status));
    QVERIFY(motors->isVisibleTo(&status));
  }
};

QTEST_MAIN(TestKukaConnection)
#include "test_kuka_connection.moc"
