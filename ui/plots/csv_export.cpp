// SPDX-License-Identifier: Apache-2.0
// writeCsv (csv_export.h): fast number formatting (std::to_chars) into a QSaveFile.
#include "plots/csv_export.h"

#include <QSaveFile>

#include <charconv>
#include <cmath>

namespace rci::ui::plots {

QString csvColumnName(int channel, const QString& joint_prefix) {
  const Signal signal = signalOfChannel(channel);
  QString name = signalKey(signal);
  const QString member = isJointSignal(signal) ? joint_prefix + QString::number(jointOfChannel(channel) + 1)
                                               : componentName(signal, jointOfChannel(channel));
  if (!member.isEmpty()) name += QLatin1Char('_') + member;
  const QString unit = signalUnit(signal);
  if (!unit.isEmpty()) name += QLatin1Char('_') + QString(unit).replace(QLatin1Char('/'), QStringLiteral("_per_"));
  return name;
}

namespace {

QByteArray headerLine(const std::vector<int>& channels, const QString& joint_prefix) {
  QByteArray line("time_s");
  for (int channel : channels) line += ',' + csvColumnName(channel, joint_prefix).toLatin1();
  return line + '\n';
}

// A value that is not there (no sensor reading, the first velocity) is an empty field.
void appendNumber(QByteArray& line, double value) {
  if (!std::isfinite(value)) return;
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  line.append(text, static_cast<qsizetype>(result.ptr - text));
}

void appendRow(QByteArray& line, const PlotBuffer& buffer, int index, const std::vector<int>& channels) {
  appendNumber(line, buffer.time(index));
  for (int channel : channels) {
    line += ',';
    appendNumber(line, buffer.value(channel, index));
  }
  line += '\n';
}

}  // namespace

bool writeCsv(const PlotBuffer& buffer, IndexRange range, const std::vector<int>& channels, const QString& path,
              QString* error, const std::function<bool(int rows_done)>& keep_going) {
  return writeCsv(buffer, range, channels, QStringLiteral("J"), path, error, keep_going);
}

bool writeCsv(const PlotBuffer& buffer, IndexRange range, const std::vector<int>& channels,
              const QString& joint_prefix, const QString& path, QString* error,
              const std::function<bool(int rows_done)>& keep_going) {
  auto fail = [error](const QString& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (range.count() <= 0) return fail(QStringLiteral("There are no samples to export: connect and let data arrive, "
                                                     "or widen the time window."));
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly))
    return fail(QStringLiteral("Cannot write %1: %2. Choose a folder you can write to.").arg(path, file.errorString()));
  QByteArray chunk = headerLine(channels, joint_prefix);
  for (int i = range.first; i < range.last; ++i) {
    appendRow(chunk, buffer, i, channels);
    const int rows = i - range.first + 1;
    if (rows % 1000 != 0 && i + 1 < range.last) continue;
    if (file.write(chunk) != chunk.size()) {
      file.cancelWriting();
      return fail(QStringLiteral("Writing %1 failed: %2. Check the free disk space.").arg(path, file.errorString()));
    }
    chunk.clear();
    if (keep_going && !keep_going(rows)) {
      file.cancelWriting();
      return fail(QStringLiteral("Export cancelled; %1 was left unchanged.").arg(path));
    }
  }
  if (!file.commit())
    return fail(QStringLiteral("Saving %1 failed: %2. Check the folder's permissions and free space.")
                    .arg(path, file.errorString()));
  return true;
}

}  // namespace rci::ui::plots
