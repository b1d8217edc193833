#include "pistondyn/io/DeckReference.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "pistondyn/common/Validation.h"
#include "pistondyn/io/LubricatedSkirtDeck.h"

namespace pistondyn::io {
namespace {

using common::formatNumber;

// A unit suffix as people write it ("kg_mm2" -> "kg·mm²"); the suffix itself if unknown.
std::string prettyUnit(const std::string& suffix) {
  static const std::map<std::string, std::string> pretty = {{"um", "µm"},
                                                            {"mm2", "mm²"},
                                                            {"kg_mm2", "kg·mm²"},
                                                            {"kg_m2", "kg·m²"},
                                                            {"g_mm2", "g·mm²"},
                                                            {"deg", "°"},
                                                            {"degC", "°C"},
                                                            {"mps2", "m/s²"},
                                                            {"m_per_s2", "m/s²"},
                                                            {"Nm", "N·m"},
                                                            {"N_m", "N·m"},
                                                            {"per_K", "1/K"},
                                                            {"mm2_per_s", "mm²/s"},
                                                            {"kg_per_m3", "kg/m³"},
                                                            {"N_per_mm", "N/mm"},
                                                            {"mm_per_s", "mm/s"},
                                                            {"mm3_per_N_m", "mm³/(N·m)"}};
  const auto it = pretty.find(suffix);
  return it == pretty.end() ? suffix : it->second;
}

std::string quotedList(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& i : items)
    out += (out.empty() ? "`" : ", `") + i + "`";
  return out;
}

// The shortest text that reads back to the value, exponents written short (2e5, 1e-9).
std::string number(double v) {
  if (std::isinf(v))
    return v > 0 ? "∞" : "−∞";
  std::string s = formatNumber(v);
  if (const auto e = s.find('e'); e != std::string::npos) {
    std::string exponent = s.substr(e + 1);
    const bool negative = !exponent.empty() && exponent[0] == '-';
    if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-'))
      exponent.erase(0, 1);
    while (exponent.size() > 1 && exponent[0] == '0')
      exponent.erase(0, 1);
    s = s.substr(0, e + 1) + (negative ? "-" : "") + exponent;
  }
  if (!s.empty() && s[0] == '-')
    s = "−" + s.substr(1);
  return s;
}

std::string interval(const Bounds& b) {
  const bool lower = std::isfinite(b.minimum), upper = std::isfinite(b.maximum);
  if (!lower && !upper)
    return "";
  if (lower && !upper)
    return (b.excludeMinimum ? "> " : "≥ ") + number(b.minimum);
  if (!lower)
    return (b.excludeMaximum ? "< " : "≤ ") + number(b.maximum);
  return std::string(b.excludeMinimum ? "(" : "[") + number(b.minimum) + ", " + number(b.maximum) +
         (b.excludeMaximum ? ")" : "]");
}

// Markdown table cells must not hold a bare '|'.
std::string cell(std::string text) {
  for (std::size_t p = text.find('|'); p != std::string::npos; p = text.find('|', p + 2))
    text.replace(p, 1, "\\|");
  return text;
}

}  // namespace

std::vector<const DeckKeyTable*> getDeckReferenceTables() {
  return {&getEngineDeckKeys(), &getLubricatedSkirtDeckKeys()};
}

std::string describeUnit(const DeckKey& k) {
  if (!k.unitText.empty())
    return k.unitText;
  switch (k.kind) {
    case DeckValueKind::Switch:
      return "`true`, `false`";
    case DeckValueKind::Text:
      return "text";
    case DeckValueKind::Choice:
      return quotedList(k.choices);
    case DeckValueKind::File:
      return "path";
    case DeckValueKind::KeyList:
      return "list of keys";
    case DeckValueKind::WholeNumber:
      return "whole number";
    case DeckValueKind::Number:
    case DeckValueKind::NumberList: {
      const auto u = k.getUnit();
      const std::string unit = u ? prettyUnit(u->suffix) : "–";
      return k.kind == DeckValueKind::NumberList ? unit + " list" : unit;
    }
  }
  return "";
}

std::string describeDefault(const DeckKey& k) {
  if (k.required)
    return "—";
  if (!k.defaultText.empty()) {
    const bool isChoice =
        std::find(k.choices.begin(), k.choices.end(), k.defaultText) != k.choices.end();
    return isChoice ? "`" + k.defaultText + "`" : k.defaultText;
  }
  if (k.defaultValue) {
    if (k.kind == DeckValueKind::Switch)
      return *k.defaultValue != 0.0 ? "`true`" : "`false`";
    return number(*k.defaultValue);
  }
  return "none";
}

std::string describeRange(const DeckKey& k) {
  std::string range = interval(k.valid);
  if (k.kind == DeckValueKind::WholeNumber)
    range = number(k.valid.minimum) + " … " + number(k.valid.maximum);
  if (k.plausible) {
    const std::string p = "plausible " + interval(*k.plausible);
    range = range.empty() ? p : range + "; " + p;
  }
  return range;
}

std::string makeDeckReferenceMarkdown() {
  std::string out = std::string(kDeckReferenceBegin) + "\n";
  for (const DeckKeyTable* t : getDeckReferenceTables()) {
    out += "\n**" + t->getTitle() + "**. " + t->getIntroduction() + "\n\n";
    out += "| key | unit / values | default | range | meaning |\n|---|---|---|---|---|\n";
    for (const DeckKey& k : t->getKeys()) {
      out += "| `" + k.path + "` | " + cell(describeUnit(k)) + " | " + cell(describeDefault(k)) +
             " | " + cell(describeRange(k)) + " | " + cell(k.meaning) + " |\n";
    }
  }
  out += "\n" + std::string(kDeckReferenceEnd) + "\n";
  return out;
}

std::string makeDeckReferenceText() {
  std::string out;
  for (const DeckKeyTable* t : getDeckReferenceTables()) {
    out += (out.empty() ? "" : "\n") + t->getTitle() + "\n";
    for (const DeckKey& k : t->getKeys()) {
      out += "  " + k.path + "  [" + describeUnit(k) + "]  default " + describeDefault(k);
      const std::string range = describeRange(k);
      if (!range.empty())
        out += "  " + range;
      out += "\n      " + k.meaning + "\n";
    }
  }
  return out;
}

}  // namespace pistondyn::io
