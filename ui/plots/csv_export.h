// SPDX-License-Identifier: Apache-2.0
// CSV export of recorded samples: a header with units ("time_s,q_J1_rad,..."), one row per sample,
// written atomically (QSaveFile): an existing file is replaced only when the whole export succeeded.
#pragma once

#include <QString>

#include <functional>
#include <vector>

#include "plots/plot_buffer.h"

namespace rci::ui::plots {

// "q_J1_rad", "tau_ext_J7_Nm", ...; with joint_prefix "A": "q_A1_rad", "q_set_A2_rad", "tau_gear_A3_Nm",
// "current_A4_A"; the sensor's "ft_Fx_N", "ft_Tz_Nm"; the count "rsi_late_answers". Any thread.
QString csvColumnName(int channel, const QString& joint_prefix = QStringLiteral("J"));

// Writes the samples of range, the channels given (in that order), to path. keep_going, if set, is
// asked every 1000 rows and cancels the export (the old file untouched) when it returns false.
// Returns false with a message saying what went wrong and what to do.
// The caller's thread (blocks on the file).
bool writeCsv(const PlotBuffer& buffer, IndexRange range, const std::vector<int>& channels, const QString& path,
              QString* error, const std::function<bool(int rows_done)>& keep_going = {});
// The same, naming the joints' columns with joint_prefix ("A" on a KUKA).
bool writeCsv(const PlotBuffer& buffer, IndexRange range, const std::vector<int>& channels,
              const QString& joint_prefix, const QString& path, QString* error,
              const std::function<bool(int rows_done)>& keep_going = {});

}  // namespace rci::ui::plots
