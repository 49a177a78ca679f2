// report.png: the gnuplot script that draws error against frame time from the rows, and gnuplot run on it.
// Data and file names reach gnuplot only as quoted data inside the script, fed through standard input.
#include "app/report/report_files.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include "app/process/child_process.h"
#include "shadelab/errors.h"
#include "shadelab/image/image.h"
#include "shadelab/io/text.h"

namespace shadelab::app {

namespace fs = std::filesystem;

namespace {

// A gnuplot string literal holding `text` as data. In single quotes gnuplot expands nothing (no backquote
// command, no @macro, no backslash escape); only ' ends the string (doubled as '') and a line break ends the
// command, so a newline in a file name would start a new gnuplot command (`system(...)` included).
// printable() writes every control byte and invalid UTF-8 as \xNN text, so no line break gets through.
std::string gnuplotString(std::string_view text) {
    std::string out = "'";
    for (char ch : printable(text)) out += ch == '\'' ? std::string("''") : std::string(1, ch);
    return out + "'";
}

std::string blockName(ShadingMode shading, LightingModel lighting, bool autoLevel) {
    std::string name = "$" + std::string(toString(shading)) + "_" + std::string(toString(lighting));
    std::replace(name.begin(), name.end(), '-', '_');
    return autoLevel ? name + "_auto" : name;
}

constexpr const char* modeColor(ShadingMode shading) {
    switch (shading) {
    case ShadingMode::Flat:
        return "#1f77b4";
    case ShadingMode::Gouraud:
        return "#2ca02c";
    case ShadingMode::Phong:
        return "#d62728";
    case ShadingMode::Toon:
        return "#9467bd";
    case ShadingMode::Exact:
        return "#000000";
    }
    return "#000000";
}

} // namespace

std::string gnuplotScript(const std::vector<ReportRow>& rows, const ReportInfo& info) {
    std::string s;
    std::set<std::string> blocks; // the data blocks written, by name
    bool hasAuto = false;
    s += "# report.png of `shadelab report`: interior mean error against median frame time, one curve per\n"
         "# shading mode and lighting model, points labelled by subdivision level. Written by shadelab;\n"
         "# re-draw with: gnuplot report.gp > report.png\n";
    s += "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
         "    set terminal pngcairo size 1280,860 font 'sans,11' noenhanced\n"
         "} else {\n"
         "    set terminal png size 1280,860 noenhanced\n"
         "}\n";
    s +=
        "set title " +
        gnuplotString(info.sceneName + ", " + std::to_string(info.width) + "x" + std::to_string(info.height) +
                      ", " + info.renderer + " (" + std::string(toString(info.backend)) + ")") +
        "\n";
    s += "set logscale xy\nset autoscale xfix\nset offsets graph 0.04, graph 0.08, 0, 0\n"
         "set format x '%g'\nset format y '%g'\nset xtics add (0.2, 0.5, 2, 5, 20, 50, 200, 500)\n"
         "set xlabel 'median frame time, ms (glFinish after each frame)'\n"
         "set ylabel 'interior mean |error| per channel, 1/255'\n"
         "set grid xtics ytics mxtics mytics lc rgb '#dddddd'\n"
         "set key inside left bottom box opaque\n"
         "set arrow from graph 0, first 1 to graph 1, first 1 nohead dt 2 lc rgb '#777777'\n"
         "set label '1/255' at graph 0.01, first 1 offset 0,0.7 tc rgb '#555555'\n";
    // The y axis is logarithmic: an error of exactly zero (an unlit scene, a flat colour) has no place on
    // it. Such points are drawn on a floor below the smallest non-zero error, marked "0 (exact)".
    double smallest = 0;
    bool anyZero = false;
    for (const ReportRow& row : rows) {
        if (row.interiorMeanError > 0)
            smallest = smallest > 0 ? std::min(smallest, row.interiorMeanError) : row.interiorMeanError;
        else
            anyZero = true;
    }
    const double zeroLevel = smallest > 0 ? smallest / 4 : 0.01;
    if (anyZero) {
        char text[400];
        std::snprintf(
            text, sizeof text,
            "set arrow from graph 0, first %.6g to graph 1, first %.6g nohead dt 3 lc rgb '#999999'\n"
            "set label '0 (exact): an error of zero is drawn on this line' at graph 0.99, first %.6g "
            "right offset 0,0.7 tc rgb '#555555'\nset yrange [%.6g:%s]\n"
            "set key inside right center box opaque\nset ytics add ('0' %.6g)\n",
            zeroLevel, zeroLevel, zeroLevel, zeroLevel / 3, smallest > 0 ? "*" : "3", zeroLevel);
        s += text;
    }
    char line[128];
    for (LightingModel lighting : kLightingModels)
        for (ShadingMode shading : kShadingModes)
            for (bool autoLevel : {false, true}) {
                std::string block;
                for (const ReportRow& row : rows) {
                    if (row.lighting != lighting || row.shading != shading || row.autoLevel != autoLevel)
                        continue;
                    std::snprintf(line, sizeof line, "%.6g %.6g \"%s\"\n", row.frameMedianMs,
                                  row.interiorMeanError > 0 ? row.interiorMeanError : zeroLevel,
                                  levelLabel(row).c_str());
                    block += line;
                }
                if (block.empty()) continue;
                const std::string name = blockName(shading, lighting, autoLevel);
                s.append(name).append(" << EOD\n").append(block).append("EOD\n");
                blocks.insert(name);
                hasAuto = hasAuto || autoLevel;
            }

    std::vector<std::string> plots;
    auto plot = [&](const std::string& block, std::string_view style, std::string_view title) {
        std::string line = block;
        line.append(" using ").append(style).append(title.empty() ? " notitle" : " title ");
        if (!title.empty()) line += gnuplotString(title);
        plots.push_back(std::move(line));
    };
    for (bool labelled : {true, false})
        for (LightingModel lighting : kLightingModels) {
            if ((lighting == info.labelledLighting) != labelled) continue;
            for (ShadingMode shading : kShadingModes) {
                const std::string name = blockName(shading, lighting, false);
                if (!blocks.count(name)) continue;
                std::string color = "lc rgb '";
                color.append(modeColor(shading)).append("'");
                std::string title(toString(shading));
                title.append(" (").append(toString(lighting)).append(" lighting)");
                plot(name,
                     std::string(labelled ? "1:2 with linespoints lw 2 pt 7 ps 1.1 dt 1 "
                                          : "1:2 with linespoints lw 1 pt 6 ps 0.8 dt 2 ") +
                         color,
                     title);
                if (!labelled) continue;
                std::string labels = "1:2:3 with labels offset char 0.9,0.55 font ',9' tc rgb '";
                labels.append(modeColor(shading)).append("'");
                plot(name, labels, {});
                const std::string autoName = blockName(shading, lighting, true);
                if (blocks.count(autoName)) plot(autoName, "1:2 with points pt 6 ps 2.6 lw 2 " + color, {});
            }
        }
    if (hasAuto) {
        std::string title = "auto subdivision (";
        title.append(toString(info.labelledLighting)).append(" lighting)");
        plots.push_back("NaN with points pt 6 ps 2.6 lw 2 lc rgb 'black' title " + gnuplotString(title));
    }
    s += "plot ";
    for (std::size_t i = 0; i < plots.size(); ++i) s.append(i ? ", \\\n     " : "").append(plots[i]);
    return s + "\n";
}

// Runs gnuplot on `script`, fed through standard input from an anonymous file, and returns what it wrote to
// standard output: no path reaches gnuplot's command line (so a folder named "-p" is not an option), and the
// PNG never touches the disk until it has been checked. --default-settings: no ~/.gnuplot runs first.
std::string runGnuplot(const std::string& script) {
    const int in = ::memfd_create("shadelab-report.gp", MFD_CLOEXEC);
    if (in < 0)
        throw RuntimeError("report: cannot hold the gnuplot script: " + std::string(std::strerror(errno)));
    std::size_t done = 0;
    while (done < script.size()) {
        const ssize_t n = ::write(in, script.data() + done, script.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            ::close(in);
            throw RuntimeError("report: cannot hold the gnuplot script: " +
                               std::string(std::strerror(errno)));
        }
        done += std::size_t(n);
    }
    ::lseek(in, 0, SEEK_SET);
    int out[2];
    if (::pipe2(out, O_CLOEXEC) != 0) {
        ::close(in);
        throw RuntimeError("report: pipe for gnuplot: " + std::string(std::strerror(errno)));
    }
    pid_t pid = 0;
    try {
        pid = startChild({"gnuplot", "--default-settings"}, ChildStreams{in, out[1], false, nullptr, true},
                         "report", "; report.png is drawn with gnuplot, Debian package gnuplot-nox");
    } catch (...) {
        ::close(in);
        ::close(out[0]);
        ::close(out[1]);
        throw;
    }
    ::close(in);
    ::close(out[1]);
    std::string png;
    char buffer[65536];
    for (;;) {
        const ssize_t n = ::read(out[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        png.append(buffer, std::size_t(n));
    }
    ::close(out[0]);
    const std::string failure = childFailure(waitForChild(pid, "report", "gnuplot"));
    if (!failure.empty())
        throw RuntimeError("report: gnuplot failed (" + failure + ") on report.gp; its messages are above");
    // gnuplot exits 0 after a write error of its own: check that what it wrote is a whole PNG.
    (void)decodePng(png, "report: gnuplot's report.png");
    return png;
}

void requireGnuplot() {
    if (!onPath("gnuplot"))
        throw RuntimeError("report: gnuplot not found on PATH; report.png is drawn with gnuplot (Debian "
                           "package gnuplot-nox: apt-get install gnuplot-nox)");
}

void plotReport(const std::vector<ReportRow>& rows, const ReportInfo& info, const fs::path& dir) {
    requireGnuplot();
    const std::string script = gnuplotScript(rows, info);
    writeReportSet(dir, {{"report.gp", script}, {"report.png", runGnuplot(script)}});
}

} // namespace shadelab::app
