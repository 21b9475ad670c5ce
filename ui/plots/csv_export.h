// SPDX-License-Identifier: Apache-2.0
// CSV export of recorded samples: a header with units ("time_s,q_J1_rad,..."), one row per sample,
// written atomically (QSaveFile): an existing file is replaced only when the whole export succeeded.
#pragma once

#include <QString>

#include <functional>
#include <vector>

#include "plots/plot_buffer.h"

namespace rci::ui::plots {

// "q_J1_rad", "tau_ext_J7_Nm", ...
QString csvColumnName(int channel);

// Writes the samples of range, the channels given (in that order), to path. keep_going, if set, is
// asked every 1000 rows and cancels the export (the old file untouched) when it returns false.
// Returns false with a message saying what went wrong and what to do.
bool writeCsv(const PlotBuffer& buffer, IndexRange range, const std::vector<int>& channels, const QString& path,
              QString* error, const std::function<bool(int rows_done)>& keep_going = {});

}  // namespace rci::ui::plots
