#include "sweep/sweep_collect.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "config/toml_reader.h"
#include "scenario/row_file.h"

namespace bdfcar::app {

using Row = std::vector<std::string>;

Row csvFields(const std::string& line) {
  Row out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
      else if (c == '"') quoted = false;
      else out.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

std::string csvLine(const Row& r) {
  std::string out;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (i) out += ',';
    if (r[i].find_first_of(",\"\n") == std::string::npos) {
      out += r[i];
    } else {
      out += '"';
      for (char c : r[i]) out += c == '"' ? std::string("\"\"") : std::string(1, c);
      out += '"';
    }
  }
  return out;
}

namespace {

std::vector<Row> readCsv(const std::string& path) {
  std::ifstream in(path);
  std::vector<Row> rows;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) rows.push_back(csvFields(line));
  return rows;
}

// The leading number of a value ("80 km/h" -> 80); false when there is none.
bool leadingNumber(const std::string& s, double& x) {
  char* end = nullptr;
  x = std::strtod(s.c_str(), &end);
  return end != s.c_str();
}

std::string gnuplotText(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out;
}

// The carpet and overlay plots; "" or why not.
std::string plotSweep(const std::string& dir, const std::vector<Row>& summary, std::size_t variables,
                      const std::string& name, std::string metric, const std::string& channel) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) return "gnuplot is not installed: no plots";
  const Row& head = summary.front();
  auto column = [&](const std::string& n) {
    for (std::size_t i = 0; i < head.size(); ++i)
      if (head[i] == n) return static_cast<int>(i);
    return -1;
  };
  if (metric.empty())
    for (const char* m : {"fmvss126_yaw_ratio_1000_pct", "iso7401_yaw_rate_response_time_s", "peak_yaw_rate_radps"})
      if (column(m) >= 0) {
        metric = m;
        break;
      }
  const int mc = column(metric);
  const std::string script = dir + "/plots.gp";
  std::ofstream s(script);
  s << "set datafile separator ','\nset terminal pngcairo noenhanced size 1000,600 font ',11'\nset grid\nset key outside right\n";
  if (variables >= 1 && mc >= 0) {
    // One data block per value of the second variable (or one block).
    // Keyed by (the label's leading number, the label): 60 km/h before 100 km/h.
    std::map<std::pair<double, std::string>, std::vector<std::pair<double, std::string>>> series;
    for (std::size_t r = 1; r < summary.size(); ++r) {
      double x;
      if (summary[r].size() <= static_cast<std::size_t>(mc) || summary[r][mc].empty()) continue;
      if (!leadingNumber(summary[r][2], x)) continue;
      const std::string label = variables >= 2 ? summary[r][3] : std::string("all");
      double order = 0;
      leadingNumber(label, order);
      series[{order, label}].push_back({x, summary[r][mc]});
    }
    s << "set output '" << dir << "/carpet.png'\nset title '" << gnuplotText(name) << "'\n";
    s << "set xlabel '" << gnuplotText(head[2]) << "'\nset ylabel '" << gnuplotText(metric) << "'\n";
    std::string plot;
    int block = 0;
    for (auto& [key, points] : series) {
      const std::string& label = key.second;
      std::sort(points.begin(), points.end());
      s << "$s" << block << " << EOD\n";
      for (const auto& [x, y] : points) s << x << "," << y << "\n";
      s << "EOD\n";
      plot += std::string(plot.empty() ? "plot " : ", ") + "$s" + std::to_string(block) +
              " using 1:2 with linespoints lw 2 title '" +
              gnuplotText(variables >= 2 ? head[3] + " = " + label : metric) + "'";
      ++block;
    }
    if (!plot.empty()) s << plot << "\n";
  }
  // The overlay: every case's channel over time (the first 40 cases).
  std::string overlay;
  for (std::size_t r = 1; r < summary.size() && r <= 40; ++r) {
    const std::string csv = dir + "/cases/" + summary[r][0] + "_telemetry.csv";
    if (!std::filesystem::exists(csv)) continue;
    std::string label;
    for (std::size_t v = 0; v < variables; ++v) label += (v ? ", " : "") + summary[r][2 + v];
    overlay += std::string(overlay.empty() ? "plot " : ", ") + "'" + csv + "' using (column('time_s')):(column('" +
               channel + "')) with lines title '" + gnuplotText(label.empty() ? summary[r][0] : label) + "'";
  }
  if (!overlay.empty()) {
    s << "set datafile columnheaders\nset output '" << dir << "/overlay.png'\nset title '" << gnuplotText(name)
      << "'\nset xlabel 'time (s)'\nset ylabel '" << gnuplotText(channel) << "'\n"
      << overlay << "\n";
  }
  s.close();
  const std::string cmd = "gnuplot '" + script + "' > '" + dir + "/plots.log' 2>&1";
  if (std::system(cmd.c_str()) != 0) return "gnuplot failed on " + script + " (see plots.log)";
  return "";
}

}  // namespace

SweepSummary collectSweep(const std::string& dir) {
  const std::vector<Row> cases = readCsv(dir + "/cases.csv");
  if (cases.size() < 1 || cases.front().size() < 2 || cases.front()[0] != "case")
    throw scenario::OutputError(dir + ": no sweep here (no cases.csv written by bdfcar sweep)");
  const std::size_t variables = cases.front().size() - 2;
  // Metric columns in the order they first appear.
  std::vector<std::string> names;
  std::vector<std::map<std::string, std::string>> values(cases.size());
  SweepSummary out;
  std::vector<std::string> status(cases.size());
  for (std::size_t i = 1; i < cases.size(); ++i) {
    ++out.cases;
    const std::vector<Row> m = readCsv(dir + "/cases/" + cases[i][0] + ".csv");
    if (m.size() != 2 || m[0].size() != m[1].size()) {
      status[i] = "missing";
      ++out.missing;
      continue;
    }
    for (std::size_t k = 0; k < m[0].size(); ++k) {
      if (std::find(names.begin(), names.end(), m[0][k]) == names.end()) names.push_back(m[0][k]);
      values[i][m[0][k]] = m[1][k];
    }
    const bool ok = values[i]["ok"] == "1";
    status[i] = ok ? "ok" : "failed";
    ++(ok ? out.ok : out.failed);
  }
  std::vector<Row> summary;
  Row head = cases.front();
  head.push_back("status");
  head.insert(head.end(), names.begin(), names.end());
  summary.push_back(head);
  for (std::size_t i = 1; i < cases.size(); ++i) {
    Row r = cases[i];
    r.resize(2 + variables);
    r.push_back(status[i]);
    for (const std::string& n : names) r.push_back(values[i].count(n) ? values[i][n] : "");
    summary.push_back(r);
  }
  std::string text;
  for (const Row& r : summary) text += csvLine(r) + "\n";
  out.summaryCsv = dir + "/summary.csv";
  scenario::RowFile f(out.summaryCsv);
  f.append(text);
  f.close();
  std::string name = "sweep", metric, channel = "yawrate_radps";
  try {
    config::Table plot = config::parseTomlFile(dir + "/plot.toml").table("plot");
    name = plot.string("name", name);
    metric = plot.string("metric", "");
    channel = plot.string("channel", channel);
  } catch (const config::ConfigError& e) {
    out.plotNote = std::string("no plot settings: ") + e.what();
  }
  const std::string why = plotSweep(dir, summary, variables, name, metric, channel);
  if (!why.empty()) out.plotNote = why;
  return out;
}

}  // namespace bdfcar::app
