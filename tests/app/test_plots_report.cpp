// Plots, report, progress line and log of the pistondyn program, at process level on the
// ideal-guide scratch deck (a run takes a second): which figures appear and that they are
// real PNGs of the stated size, a missing gnuplot, the report rendered by headless
// Chromium (skipped without it) with its images decoded here and compared byte for byte,
// the progress line on a terminal and off it, --log-level.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "PlotChecks.h"
#include "ScratchDeck.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;

namespace {

class ProgramPlots : public ScratchDeck {
 protected:
  // Runs `pistondyn <args>` with `env` before it; stdout and stderr to files in dir_.
  int program(const std::string& args, const std::string& env = "") const {
    const std::string cmd = env + " " + std::string(PISTONDYN_EXE) + " " + args + " > " +
                            (dir_ / "stdout.txt").string() + " 2> " +
                            (dir_ / "stderr.txt").string();
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string stdoutText() const { return readFile(dir_ / "stdout.txt"); }
  std::string err() const { return readFile(dir_ / "stderr.txt"); }
  std::string runArgs(const fs::path& out) const {
    return "run " + deck() + " --out " + out.string();
  }
};

TEST_F(ProgramPlots, ARunDrawsTheCrankTrainFiguresOfTheIdealGuide) {
  const fs::path out = dir_ / "results";
  ASSERT_EQ(program(runArgs(out) + " --quiet"), 0) << err();
  // The ideal guide has no skirt columns: the two crank-train figures only, each a PNG of
  // 1200 px by 110 + 360 px per panel (two panels).
  EXPECT_EQ(listPngs(out / "plots"),
            (std::vector<std::string>{"crank_train_forces.png", "side_force.png"}));
  for (const char* f : {"crank_train_forces.png", "side_force.png"}) {
    const PngSize size = readPngSize(out / "plots" / f);
    EXPECT_EQ(size.width, 1200) << f;
    EXPECT_EQ(size.height, 830) << f;
  }
  EXPECT_NE(stdoutText().find("2 figures"), std::string::npos) << stdoutText();
  // --no-plot: none; `plot` draws them afterwards.
  const fs::path bare = dir_ / "bare";
  ASSERT_EQ(program(runArgs(bare) + " --quiet --no-plot"), 0) << err();
  EXPECT_FALSE(fs::exists(bare / "plots"));
  ASSERT_EQ(program("plot " + bare.string()), 0) << err();
  EXPECT_EQ(listPngs(bare / "plots").size(), 2u);
  // Figures of another run in the folder are replaced, stale ones removed.
  std::ofstream(bare / "plots" / "field_map_90deg.png") << "stale";
  ASSERT_EQ(program("plot " + bare.string()), 0) << err();
  EXPECT_EQ(listPngs(bare / "plots").size(), 2u);
}

TEST_F(ProgramPlots, AMissingGnuplotIsAClearMessage) {
  const fs::path out = dir_ / "results";
  // run: the results are written, a warning says why there are no plots, exit 0.
  ASSERT_EQ(program(runArgs(out) + " --quiet", "PISTONDYN_GNUPLOT=/no/such/gnuplot"), 0) << err();
  EXPECT_TRUE(fs::exists(out / "cycle.csv"));
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_FALSE(fs::exists(out / "plots"));
  EXPECT_NE(err().find("warning: no plots"), std::string::npos) << err();
  EXPECT_NE(err().find("PISTONDYN_GNUPLOT=/no/such/gnuplot is not an executable file"),
            std::string::npos)
      << err();
  // plot: exit 3, no figure. Without PISTONDYN_GNUPLOT and no gnuplot on PATH: what to install.
  EXPECT_EQ(program("plot " + out.string(), "env -u PISTONDYN_GNUPLOT PATH=/nonexistent"), 3);
  EXPECT_NE(err().find("gnuplot was not found on PATH: install it"), std::string::npos) << err();
  EXPECT_FALSE(fs::exists(out / "plots"));
  // A gnuplot that fails (false exits 1): exit 3, its complaint passed on, nothing written.
  EXPECT_EQ(program("plot " + out.string(), "PISTONDYN_GNUPLOT=/bin/false"), 3);
  EXPECT_NE(err().find("gnuplot failed"), std::string::npos) << err();
  EXPECT_FALSE(fs::exists(out / "plots"));
}

TEST_F(ProgramPlots, PlotAndReportRejectAFolderThatHoldsNoResults) {
  fs::create_directories(dir_ / "empty");
  EXPECT_EQ(program("plot " + (dir_ / "empty").string()), 1);
  EXPECT_NE(err().find("cycle.csv: missing"), std::string::npos) << err();
  EXPECT_EQ(program("report " + (dir_ / "nowhere").string()), 1);
  EXPECT_NE(err().find("not a folder"), std::string::npos) << err();
  EXPECT_FALSE(fs::exists(dir_ / "nowhere"));
}

// The report: self-contained (no address it would fetch), every figure embedded (decoded
// here and compared with the PNG), and, in headless Chromium, a page whose script ran to
// the end without an error, filled in the animation's status and shows every image.
TEST_F(ProgramPlots, ReportIsSelfContainedAndRendersInChromium) {
  const fs::path out = dir_ / "results";
  ASSERT_EQ(program(runArgs(out) + " --quiet --no-plot"), 0) << err();
  ASSERT_EQ(program("report " + out.string()), 0) << err();
  const std::string html = readFile(out / "report.html");
  checkReportEmbedsThePlots(html, out / "plots");
  EXPECT_NE(html.find("Gasoline passenger-car engine"), std::string::npos);
  EXPECT_NE(html.find("imep"), std::string::npos);
  EXPECT_NE(html.find("<pre id=\"deck\">"), std::string::npos);  // the deck's text
  EXPECT_NE(html.find("holds the piston on the bore axis"), std::string::npos);
  renderInChromium(out / "report.html", 2);
}

// The text between `open` and the next `close` after it ("" if absent).
std::string between(const std::string& text, const std::string& open, const std::string& close) {
  const std::size_t a = text.find(open);
  if (a == std::string::npos)
    return "";
  const std::size_t b = text.find(close, a);
  return text.substr(a, b == std::string::npos ? std::string::npos : b - a);
}

// `value` to 3 significant digits in fixed notation (the report's rule for a figure of
// 1 ... 999), written here independently of the program's formatting.
std::string threeDigits(double value) {
  const int decimals = std::max(0, 2 - static_cast<int>(std::floor(std::log10(std::abs(value)))));
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// Issue 37: the report a piston engineer reads. A short run (one cycle on the ideal guide):
// the headline shows the figures in engineering units (kPa, bar) with no number in
// exponent form, the run that was not checked for periodicity says "not converged"
// (cycles_to_converge is null) in the headline and the summary table, and the summary table
// shows the displacement in cm³ (the 348.7 cm³: pi/4 x 74.5 mm² x 80 mm).
TEST_F(ProgramPlots, ReportHeadlineIsInEngineeringUnits) {
  const fs::path out = dir_ / "results";
  ASSERT_EQ(program(runArgs(out) + " --quiet --no-plot"), 0) << err();
  ASSERT_EQ(program("report " + out.string()), 0) << err();
  const std::string html = readFile(out / "report.html");
  const std::string headline = between(html, "<section id=\"headline\">", "</section>");
  ASSERT_FALSE(headline.empty()) << html.substr(0, 3000);
  const std::regex exponent("[0-9][eE][+-]?[0-9]");
  EXPECT_FALSE(std::regex_search(headline, exponent)) << headline;
  EXPECT_NE(headline.find(" kPa<"), std::string::npos) << headline;
  EXPECT_NE(headline.find("imep"), std::string::npos) << headline;
  // The peak cylinder pressure in bar with its crank angle, from summary.json's Pa.
  const nlohmann::json summary = nlohmann::json::parse(readFile(out / "summary.json"));
  const nlohmann::json& r = summary["results"];
  const std::string peak = threeDigits(r["peak_cylinder_pressure_Pa"].get<double>() / 1e5);
  EXPECT_NE(headline.find(">" + peak + " bar at "), std::string::npos) << peak << "\n" << headline;
  EXPECT_NE(headline.find(threeDigits(r["imep_kPa"].get<double>()) + " kPa"), std::string::npos)
      << headline;
  // One cycle, until_periodic off: not converged, and no number of cycles to converge.
  ASSERT_TRUE(r["cycles_to_converge"].is_null());
  EXPECT_NE(headline.find("not converged (1 cycle run)"), std::string::npos) << headline;
  const std::string table = between(html, "<table class=\"summary\" id=\"summary\">", "</table>");
  ASSERT_FALSE(table.empty());
  EXPECT_NE(table.find("<td>cycles to converge</td><td class=\"num\">not converged</td>"),
            std::string::npos)
      << table;
  EXPECT_FALSE(std::regex_search(table, std::regex("[0-9][eE]\\+[0-9]"))) << table;
  const double displacement_cm3 = M_PI / 4.0 * 7.45 * 7.45 * 8.0;  // 348.73: 4 digits
  char expected[32];
  std::snprintf(expected, sizeof expected, "%.1f", displacement_cm3);
  EXPECT_NE(table.find(std::string("<td>displacement</td><td class=\"num\">") + expected +
                       "</td><td>cm³</td>"),
            std::string::npos)
      << expected << "\n" << table;
  EXPECT_NE(table.find("<td>peak cylinder pressure</td><td class=\"num\">" + peak +
                       "</td><td>bar</td>"),
            std::string::npos)
      << table;
  // The ideal guide has no nodal fields: no field map, and the page still renders.
  EXPECT_EQ(html.find("id=\"field-frames\""), std::string::npos);
}

// The inputs table: each input in its deck key's unit with the source the deck's comment
// marks (EST, [V]), an override marked --set with its value.
TEST_F(ProgramPlots, ReportInputsTableNamesEachValuesSource) {
  const fs::path out = dir_ / "results";
  ASSERT_EQ(program(runArgs(out) + " --quiet --no-plot --set geometry.crank_offset_mm=0.2"), 0)
      << err();
  ASSERT_EQ(program("report " + out.string()), 0) << err();
  const std::string html = readFile(out / "report.html");
  const std::string table = between(html, "<table class=\"summary inputs\" id=\"inputs\">", "</table>");
  ASSERT_FALSE(table.empty()) << html.substr(0, 3000);
  auto row = [&](const std::string& key) { return between(table, "<code>" + key + "</code>", "</tr>"); };
  // The deck: "conrod_length_mm: 140.0  # EST: L/r = 3.5, ..." and "bore_mm: 74.5  # [V]".
  EXPECT_NE(row("geometry.conrod_length_mm").find("<td class=\"num\">140</td><td>mm</td><td>EST</td>"),
            std::string::npos)
      << row("geometry.conrod_length_mm");
  EXPECT_NE(table.find("<tr class=\"est\"><td><code>geometry.conrod_length_mm</code>"),
            std::string::npos);
  EXPECT_NE(row("geometry.bore_mm").find("<td class=\"num\">74.5</td><td>mm</td><td>[V]</td>"),
            std::string::npos)
      << row("geometry.bore_mm");
  EXPECT_NE(row("geometry.crank_offset_mm").find("<td class=\"num\">0.2</td><td>mm</td><td>--set</td>"),
            std::string::npos)
      << row("geometry.crank_offset_mm");
  // Values in the deck's units, not SI: no bore of 0.0745.
  EXPECT_EQ(table.find("0.0745"), std::string::npos);
  EXPECT_NE(html.find("<pre id=\"deck\">"), std::string::npos);
}

// The report's animated map from a field_frames file written here (2 frames x 2 x 2 nodes,
// rows in no particular order): each field in its display unit, quantised linearly from its
// lowest value (0 .. 255) to the top of its colour scale, which is the largest value when
// it occurs twice (the cycle maps' 99th-percentile rule keeps a repeated maximum); the
// map's script runs in Chromium. A file with a node missing is refused: exit 1, the file
// named, no report.
TEST_F(ProgramPlots, ReportAnimatedMapHoldsTheFramesInDisplayUnits) {
  const fs::path out = dir_ / "results";
  ASSERT_EQ(program(runArgs(out) + " --quiet --no-plot"), 0) << err();
  // film_pressure_Pa in MPa: frame 0 (y 0: 0, 1.6; y 5: 4, 1), frame 10 (y 0: 4, 3; y 5: 1,
  // 0.5): no value on a half step of the 255 levels, where rounding would depend on the
  // last bit of the conversion.
  const std::string rows =
      "10,10,5,0.5e6,1\n0,-10,0,0,1\n0,10,5,1e6,0.25\n10,-10,0,4e6,1\n0,10,0,1.6e6,0.5\n"
      "10,10,0,3e6,1\n0,-10,5,4e6,1\n10,-10,5,1e6,0.75\n";
  std::ofstream(out / "field_frames_thrust.csv")
      << "crank_angle_deg,phi_deg,y_mm,film_pressure_Pa,fill_fraction\n" << rows;
  ASSERT_EQ(program("report " + out.string()), 0) << err();
  const std::string html = readFile(out / "report.html");
  const std::string tag = "<script type=\"application/json\" id=\"field-frames\">";
  const std::string json = between(html, tag, "</script>");
  ASSERT_FALSE(json.empty());
  const nlohmann::json d = nlohmann::json::parse(json.substr(tag.size()));
  EXPECT_EQ(d["frames_deg"], nlohmann::json::parse("[0, 10]"));
  ASSERT_EQ(d["regions"].size(), 1u);
  EXPECT_EQ(d["regions"][0]["phi_deg"], nlohmann::json::parse("[-10, 10]"));
  EXPECT_EQ(d["regions"][0]["y_mm"], nlohmann::json::parse("[0, 5]"));
  ASSERT_EQ(d["fields"].size(), 2u);
  const nlohmann::json& p = d["fields"][0];
  EXPECT_EQ(p["name"], "film_pressure");
  EXPECT_EQ(p["unit"], "MPa");
  EXPECT_EQ(p["lo"], "0");
  EXPECT_EQ(p["top"], "4.00");
  // Frame-major, then height, then angle: the values above in MPa over 4 MPa x 255.
  const std::vector<double> pressure_MPa = {0, 1.6, 4, 1, 4, 3, 1, 0.5};
  const std::string bytes = decodeBase64(p["data"][0].get<std::string>());
  ASSERT_EQ(bytes.size(), pressure_MPa.size());
  for (std::size_t k = 0; k < bytes.size(); ++k)
    EXPECT_EQ(static_cast<unsigned char>(bytes[k]), std::lround(255.0 * pressure_MPa[k] / 4.0)) << k;
  const nlohmann::json& fill = d["fields"][1];
  EXPECT_EQ(fill["name"], "fill_fraction");
  EXPECT_EQ(fill["blues"], true);
  EXPECT_EQ(fill["lo"], "0.250");
  const std::string fillBytes = decodeBase64(fill["data"][0].get<std::string>());
  ASSERT_EQ(fillBytes.size(), 8u);
  EXPECT_EQ(static_cast<unsigned char>(fillBytes[0]), 255);  // 1 at the top of 0.25 .. 1
  EXPECT_EQ(static_cast<unsigned char>(fillBytes[1]), 85);   // 0.5: 1/3 of 255
  EXPECT_EQ(static_cast<unsigned char>(fillBytes[3]), 0);    // 0.25 at the bottom
  EXPECT_EQ(static_cast<unsigned char>(fillBytes[6]), 170);  // 0.75: 2/3 of 255
  renderInChromium(out / "report.html", 2, {"data-field-map=\"ready\""});

  // A node missing from the last frame: refused before anything is written.
  fs::remove(out / "report.html");
  std::ofstream(out / "field_frames_thrust.csv")
      << "crank_angle_deg,phi_deg,y_mm,film_pressure_Pa,fill_fraction\n"
      << rows.substr(0, rows.rfind('\n', rows.size() - 2) + 1);
  EXPECT_EQ(program("report " + out.string()), 1);
  EXPECT_NE(err().find("field_frames_thrust.csv"), std::string::npos) << err();
  EXPECT_FALSE(fs::exists(out / "report.html"));
}

// The progress line: on a terminal (a pseudo-terminal from script(1)) a line with the
// cycle, crank angle and time left, rewritten with carriage returns; off a terminal no
// carriage return at all; --quiet: none.
TEST_F(ProgramPlots, ProgressLineOnATerminalOnlyAndNeverWithQuiet) {
  if (std::system("command -v script > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "script(1) (util-linux) is not installed: no pseudo-terminal";
  // Four ideal-guide cycles (about a second, machine-dependent), with the line shown from
  // the start (PISTONDYN_PROGRESS_AFTER_S=0) so that the test does not depend on the speed.
  setenv("PISTONDYN_PROGRESS_AFTER_S", "0", 1);
  const std::string longer = " --no-plot --set simulation.cycles=4";
  const fs::path tty = dir_ / "tty.txt";
  const std::string inner = std::string(PISTONDYN_EXE) + " " + runArgs(dir_ / "r1") + longer +
                            " > /dev/null";
  const std::string cmd = "script -qefc '" + inner + "' " + tty.string() + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << readFile(tty);
  const std::string shown = readFile(tty);
  EXPECT_TRUE(std::regex_search(shown, std::regex("\rpistondyn: cycle [1-4] of 4, crank angle +"
                                                  "[0-9.]+ deg, +[0-9]+ % done, about [0-9]+ s left")))
      << shown;
  // Off a terminal (stderr to a file), the same run: no carriage return.
  ASSERT_EQ(program(runArgs(dir_ / "r2") + longer), 0) << err();
  EXPECT_EQ(err().find('\r'), std::string::npos) << err();
  // --quiet on a terminal: no progress line.
  const std::string quiet = "script -qefc '" + inner + " --quiet' " + tty.string() +
                            " > /dev/null 2>&1";
  ASSERT_EQ(std::system(quiet.c_str()), 0) << readFile(tty);
  EXPECT_EQ(readFile(tty).find("crank angle"), std::string::npos) << readFile(tty);
  unsetenv("PISTONDYN_PROGRESS_AFTER_S");
}

TEST_F(ProgramPlots, LogLevel) {
  ASSERT_EQ(program(runArgs(dir_ / "r") + " --quiet --no-plot --log-level info"), 0) << err();
  EXPECT_NE(err().find("pistondyn [info] run: deck " + deck()), std::string::npos) << err();
  ASSERT_EQ(program("plot " + (dir_ / "r").string() + " --log-level debug"), 0) << err();
  EXPECT_NE(err().find("pistondyn [debug] plot: running"), std::string::npos) << err();
  // The default (warn) says nothing on a good run.
  ASSERT_EQ(program("plot " + (dir_ / "r").string()), 0) << err();
  EXPECT_EQ(err(), "");
  EXPECT_EQ(program("plot " + (dir_ / "r").string() + " --log-level loud"), 2);
  EXPECT_NE(err().find("usage: pistondyn"), std::string::npos) << err();
}

// --help names the new options with their defaults, and the new commands.
TEST(ProgramHelp, NamesPlotReportAndTheirOptions) {
  const fs::path log = fs::temp_directory_path() / ("pistondyn_help_" + std::to_string(::getpid()));
  auto help = [&](const std::string& args) {
    const std::string cmd = std::string(PISTONDYN_EXE) + " " + args + " > " + log.string();
    EXPECT_EQ(std::system(cmd.c_str()), 0) << args;
    return readFile(log);
  };
  const std::string top = help("--help");
  for (const char* text : {"plot", "report"})
    EXPECT_NE(top.find(text), std::string::npos) << text << "\n" << top;
  const std::string run = help("run --help");
  for (const char* text : {"--no-plot", "--quiet", "--log-level", "default: warn", "gnuplot",
                           "1 s", "15 s"})
    EXPECT_NE(run.find(text), std::string::npos) << text << "\n" << run;
  const std::string plot = help("plot --help");
  for (const char* text : {"DIR", "--log-level", "firing TDC", "kN", "um", "mrad", "MPa",
                           "PISTONDYN_GNUPLOT", "Exit codes"})
    EXPECT_NE(plot.find(text), std::string::npos) << text << "\n" << plot;
  const std::string report = help("report --help");
  for (const char* text : {"DIR", "self-contained", "base64", "exaggerated", "Exit codes"})
    EXPECT_NE(report.find(text), std::string::npos) << text << "\n" << report;
  fs::remove(log);
}

}  // namespace
