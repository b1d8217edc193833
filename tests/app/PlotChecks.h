#pragma once
// Checks of the program's figures and report shared by tests/app: PNG files read by their
// own header (not by the code that wrote them), the report's base64 images decoded here
// and compared with the PNG files, and the report rendered by headless Chromium (Debian
// package chromium; the check is skipped when it is not installed).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace pistondyn_test {

namespace fs = std::filesystem;

inline std::string readBinary(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The *.png files of a folder, sorted; empty if it does not exist.
inline std::vector<std::string> listPngs(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    return names;
  for (const auto& e : fs::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

struct PngSize {
  long width = 0, height = 0;
};

// Width and height from the IHDR chunk after the PNG signature; 0 x 0 if not a PNG.
inline PngSize readPngSize(const fs::path& p) {
  const std::string b = readBinary(p);
  const std::string signature = "\x89PNG\r\n\x1a\n";
  if (b.size() < 24 || b.compare(0, 8, signature) != 0 || b.compare(12, 4, "IHDR") != 0)
    return {};
  auto be32 = [&](std::size_t at) {
    long v = 0;
    for (std::size_t i = 0; i < 4; ++i)
      v = (v << 8) | static_cast<unsigned char>(b[at + i]);
    return v;
  };
  return {be32(16), be32(20)};
}

inline std::string decodeBase64(const std::string& text) {
  std::string out;
  unsigned buffer = 0;
  int bits = 0;
  for (char c : text) {
    int v;
    if (c >= 'A' && c <= 'Z') v = c - 'A';
    else if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
    else if (c >= '0' && c <= '9') v = c - '0' + 52;
    else if (c == '+') v = 62;
    else if (c == '/') v = 63;
    else continue;  // '=' padding
    buffer = (buffer << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((buffer >> bits) & 0xff);
    }
  }
  return out;
}

// Every PNG of plotDir is embedded in the page exactly as the file holds it, as many
// images as files, and the page references nothing it would have to fetch.
inline void checkReportEmbedsThePlots(const std::string& html, const fs::path& plotDir) {
  // Plain searching: std::regex recurses per character and overflows the stack on
  // images of a few hundred kilobytes.
  const std::string head = "<img alt=\"", data = "\" src=\"data:image/png;base64,";
  std::vector<std::string> embedded;
  for (std::size_t at = html.find(head); at != std::string::npos; at = html.find(head, at + 1)) {
    const std::size_t nameEnd = html.find(data, at);
    ASSERT_NE(nameEnd, std::string::npos) << html.substr(at, 200);
    const std::string name = html.substr(at + head.size(), nameEnd - at - head.size()) + ".png";
    const std::size_t begin = nameEnd + data.size(), end = html.find('"', begin);
    ASSERT_NE(end, std::string::npos);
    embedded.push_back(name);
    EXPECT_TRUE(decodeBase64(html.substr(begin, end - begin)) == readBinary(plotDir / name))
        << name << ": the embedded image is not the file's bytes";
  }
  std::sort(embedded.begin(), embedded.end());
  EXPECT_EQ(embedded, listPngs(plotDir));
  EXPECT_FALSE(embedded.empty());
  for (const char* fetch : {"src=\"http", "href=\"http", "src='http", "url(http", "@import",
                            "<link", "src=\"//"})
    EXPECT_EQ(html.find(fetch), std::string::npos) << fetch;
}

inline std::string findChromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    const std::string cmd = std::string("command -v ") + name + " > /dev/null 2>&1";
    if (std::system(cmd.c_str()) == 0)
      return name;
  }
  return "";
}

// Renders the page headless and checks the DOM after its scripts ran: no error caught by
// the page's error handler or printed on the console, `images` images decoded with a width,
// <body> carries each of `bodyAttributes` (e.g. data-field-map="ready": the field map's
// script ran to its end), and, for a run's report (`animated`), the animation's script ran
// to its end and wrote its status.
inline void renderInChromium(const fs::path& page, int images,
                             const std::vector<std::string>& bodyAttributes = {},
                             bool animated = true) {
  const std::string chromium = findChromium();
  if (chromium.empty())
    GTEST_SKIP() << "chromium is not installed (Debian: apt-get install chromium): the report "
                    "was not rendered";
  const fs::path work = page.parent_path() / "chromium";
  fs::create_directories(work);
  const std::string cmd =
      "timeout 120 " + chromium +
      " --headless --no-sandbox --disable-gpu --no-first-run --disable-extensions "
      "--enable-logging=stderr --v=0 --virtual-time-budget=3000 --user-data-dir=" +
      (work / "profile").string() + " --dump-dom file://" + fs::absolute(page).string() + " > " +
      (work / "dom.html").string() + " 2> " + (work / "console.txt").string();
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << cmd << "\n" << readBinary(work / "console.txt");
  const std::string dom = readBinary(work / "dom.html");
  const std::string console = readBinary(work / "console.txt");
  // The page's script records its state as attributes of <body> (its own text mentions
  // them too, so only the tag counts).
  const std::size_t bodyAt = dom.find("<body");
  ASSERT_NE(bodyAt, std::string::npos) << dom.substr(0, 2000);
  const std::string body = dom.substr(bodyAt, dom.find('>', bodyAt) - bodyAt);
  EXPECT_EQ(body.find("data-js-error"), std::string::npos) << body;
  EXPECT_EQ(console.find("Uncaught"), std::string::npos) << console;
  if (animated) {
    EXPECT_NE(body.find("data-animation=\"ready\""), std::string::npos) << body;
  }
  EXPECT_NE(body.find("data-images-shown=\"" + std::to_string(images) + "\""), std::string::npos)
      << body;
  for (const std::string& attribute : bodyAttributes)
    EXPECT_NE(body.find(attribute), std::string::npos) << attribute << "\n" << body;
  if (!animated) {
    fs::remove_all(work);
    return;
  }
  const std::string statusText = "<p id=\"animation-status\">crank angle ";
  const std::size_t at = dom.find(statusText);
  ASSERT_NE(at, std::string::npos) << "the script did not fill in the animation's status";
  EXPECT_TRUE(std::regex_match(dom.substr(at + statusText.size(), 40),
                               std::regex("[0-9]+\\.[0-9] deg .*")))
      << dom.substr(at, 100);
  fs::remove_all(work);
}

}  // namespace pistondyn_test
