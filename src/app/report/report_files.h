// Private to src/app/report/: the report's files as text, so that runReport can make them all before it
// writes any (report_files.cpp: the CSV, the JSON and the set; report_plot.cpp: the gnuplot script and
// picture). The public entry points are in report.h.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "app/report/report.h"

namespace shadelab::app {

std::string reportCsv(const std::vector<ReportRow>& rows);
std::string reportJson(const std::vector<ReportRow>& rows, const ReportInfo& info);
// The gnuplot script of report.gp, its data inline.
std::string gnuplotScript(const std::vector<ReportRow>& rows, const ReportInfo& info);
// report.png as gnuplot draws it from `script`; RuntimeError naming gnuplot if it cannot run or fails.
std::string runGnuplot(const std::string& script);
// Writes each (name, text) into `dir` as one set: all or, on a failure before the renames, none. Each of
// `stale` (an earlier run's file that this set has no new version of, e.g. report.png under --no-plot) is
// removed with the renames, so the folder never mixes two runs; returns the names it removed.
std::vector<std::string> writeReportSet(const std::filesystem::path& dir,
                                        const std::vector<std::pair<std::string, std::string>>& files,
                                        const std::vector<std::string>& stale = {});

} // namespace shadelab::app
