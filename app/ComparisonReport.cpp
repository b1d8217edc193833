#include "ComparisonReport.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "HtmlReport.h"
#include "ReportSummary.h"
#include "SvgChart.h"

namespace pistondyn::app {
namespace {

namespace fs = std::filesystem;

const char* kStyle = R"(body{font-family:sans-serif;max-width:1250px;margin:1em auto;padding:0 1em;color:#222}
table.cases{border-collapse:collapse;margin:0.5em 0}
table.cases td,table.cases th{border:1px solid #ccc;padding:2px 8px;text-align:left}
table.cases td.num{font-family:monospace;text-align:right}
table.cases thead th{background:#eef2f7}
figure{margin:1em 0}figure img{max-width:100%;border:1px solid #ddd})";

// The headline labels of every case, in the order the first case that has each gives them.
std::vector<std::string> collectLabels(const std::vector<std::vector<HeadlineItem>>& headlines) {
  std::vector<std::string> labels;
  for (const auto& items : headlines) {
    for (const HeadlineItem& item : items) {
      if (std::find(labels.begin(), labels.end(), item.label) == labels.end())
        labels.push_back(item.label);
    }
  }
  return labels;
}

}  // namespace

std::string makeComparisonHtml(const std::string& title, const std::vector<ComparisonCase>& cases,
                               const std::vector<std::string>& pngPaths,
                               const std::string& plotNote) {
  std::vector<std::vector<HeadlineItem>> headlines;
  for (const ComparisonCase& c : cases)
    headlines.push_back(makeHeadline(c.folder));
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>pistondyn "
          "comparison: "
       << escapeHtml(title) << "</title>\n<style>" << kStyle << "</style></head>\n<body>\n"
       << "<h1>pistondyn comparison: " << escapeHtml(title) << "</h1>\n"
       << "<p>" << cases.size()
       << " finished cases side by side: the headline figures of each case's last cycle in "
          "engineering units (each case's folder holds its summary.json with every digit; "
          "<code>pistondyn report</code> on a case's folder gives its full report), then the "
          "cases' curves on common axes. A failed case is listed in comparison.csv, not "
          "here.</p>\n";
  html << "<table class=\"cases\" id=\"cases\"><thead><tr><th></th>";
  for (const ComparisonCase& c : cases) {
    html << "<th>" << escapeHtml(c.label) << "<br><code>"
         << escapeHtml(fs::path(c.folder.directory).filename().string()) << "</code></th>";
  }
  html << "</tr></thead><tbody>\n";
  for (const std::string& label : collectLabels(headlines)) {
    html << "<tr><th>" << escapeHtml(label) << "</th>";
    for (const auto& items : headlines) {
      const auto at = std::find_if(items.begin(), items.end(),
                                   [&](const HeadlineItem& i) { return i.label == label; });
      html << "<td class=\"num\">" << (at == items.end() ? "–" : escapeHtml(at->value)) << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</tbody></table>\n<h2>The cases' curves</h2>\n";
  writeEmbeddedFigures(html, pngPaths, plotNote);
  html << "<script>window.addEventListener('error', function (e) {\n"
          "  document.body.setAttribute('data-js-error', String(e.message));\n});\n"
          "window.addEventListener('load', function () {\n"
          "  var shown = 0, imgs = document.querySelectorAll('figure img');\n"
          "  for (var k = 0; k < imgs.length; ++k) { if (imgs[k].complete && imgs[k].naturalWidth "
          "> 0) { ++shown; } }\n"
          "  document.body.setAttribute('data-images-shown', String(shown));\n});</script>\n"
          "</body></html>\n";
  return html.str();
}

}  // namespace pistondyn::app
