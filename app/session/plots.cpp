#include "session/plots.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace bdfcar::app {

namespace {

// Lane limits of the course as gnuplot data blocks (x y, blank line between segments).
void writeCourse(std::ofstream& s, const scenario::Iso3888Course& c) {
  s << "$course << EOD\n";
  for (const auto& l : c.lanes) {
    // Comma-separated like the telemetry (the script sets the separator once).
    s << l.x0 << "," << l.centreY + 0.5 * l.width << "\n" << l.x1 << "," << l.centreY + 0.5 * l.width << "\n\n";
    s << l.x0 << "," << l.centreY - 0.5 * l.width << "\n" << l.x1 << "," << l.centreY - 0.5 * l.width << "\n\n";
  }
  s << "EOD\n";
}

}  // namespace

std::string plotDrive(const std::string& csv, const std::string& outDir,
                      const std::optional<scenario::Iso3888Course>& course, const std::string& title) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) return "gnuplot is not installed: no plots";
  std::filesystem::create_directories(outDir);
  const std::string script = (std::filesystem::path(outDir) / "plots.gp").string();
  {
    std::ofstream s(script);
    s << "set datafile separator ','\nset terminal pngcairo size 1200,500 font ',11'\nset grid\n";
    if (course) writeCourse(s, *course);
    s << "set output '" << (std::filesystem::path(outDir) / "path.png").string() << "'\n";
    s << "set title '" << title << ": path'\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nset key outside below\n";
    if (course) {
      s << "set xrange [" << course->startX - 20 << ":" << course->endX + 20 << "]\n";
      s << "set yrange [" << course->lanes[0].centreY - 4 << ":" << course->lanes[1].centreY + 4 << "]\n";
    }
    s << "plot '" << csv << "' using 2:3 with lines lw 2 title 'centre of mass'";
    if (course) s << ", $course with lines lc rgb 'orange' lw 2 title 'lane limits'";
    s << "\nset output '" << (std::filesystem::path(outDir) / "lateral_acceleration.png").string() << "'\n";
    s << "unset xrange\nunset yrange\nset title '" << title << ": lateral acceleration'\n";
    s << "set xlabel 'time (s)'\nset ylabel 'a_y (m/s^2)'\n";
    s << "plot '" << csv << "' using 1:10 with lines lw 2 title 'a_y (chassis y)'\n";
  }
  const std::string cmd = "gnuplot '" + script + "' 2>&1";
  if (std::system(cmd.c_str()) != 0) return "gnuplot failed on " + script;
  return "";
}

std::string plotCsvColumns(const std::vector<CsvPlot>& plots, const std::string& script) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) return "gnuplot is not installed: no plots";
  {
    std::ofstream s(script);
    s << "set datafile separator ','\nset datafile columnheaders\nset terminal pngcairo noenhanced size 1000,600 "
         "font ',11'\nset grid\nset key outside right\n";
    for (const CsvPlot& p : plots) {
      s << "set output '" << p.png << "'\nset title '" << p.title << "'\nset xlabel '" << p.x << "'\nset ylabel ''\nplot ";
      for (size_t k = 0; k < p.ys.size(); ++k)
        s << (k ? ", " : "") << "'" << p.csv << "' using (column('" << (p.xs.empty() ? p.x : p.xs[k]) << "')):(column('" << p.ys[k]
          << "')) with lines lw 2 title '" << p.ys[k] << "'";
      s << "\n";
    }
  }
  const std::string cmd = "gnuplot '" + script + "' 2>&1";
  if (std::system(cmd.c_str()) != 0) return "gnuplot failed on " + script;
  return "";
}

}  // namespace bdfcar::app
