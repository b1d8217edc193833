// The Python module pistondyn (its compiled part, pistondyn._pistondyn; the package's
// __init__.py adds the Python-side conveniences). Thin bindings over pistondyn::io: decks
// loaded and checked with overrides, runs (the same runDeck() and summary text as `pistondyn
// run`), result folders read back, sweeps. Simulations release the GIL, so Python threads
// can run several at once (each its own model, as sweeps do).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/ResultFolder.h"
#include "pistondyn/io/RunDeck.h"
#include "pistondyn/io/SweepDeck.h"
#include "pistondyn/io/SweepRun.h"
#include "pistondyn/io/Version.h"
#include "pistondyn/plugin/CycleSimulation.h"

namespace py = pybind11;
using namespace pistondyn;

namespace {

// A table's rows as a 2-D float64 array (rows x columns).
py::array_t<double> toArray(const std::vector<std::vector<double>>& rows, std::size_t columns) {
  py::array_t<double> a({rows.size(), columns});
  auto view = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < columns && j < rows[i].size(); ++j)
      view(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = rows[i][j];
  return a;
}

py::object inputValue(const io::ResolvedInput::Value& v) {
  return std::visit([](const auto& x) -> py::object { return py::cast(x); }, v);
}

// What a run hands back: summary.json's text, the columns and the rows.
py::dict runResult(const std::string& summaryJson, const std::vector<std::string>& columns,
                   const std::vector<std::vector<double>>& rows, const std::string& folder) {
  py::dict d;
  d["summary_json"] = summaryJson;
  d["columns"] = columns;
  d["rows"] = toArray(rows, columns.size());
  d["folder"] = folder;
  return d;
}

}  // namespace

PYBIND11_MODULE(_pistondyn, m) {
  m.doc() = "pistondyn: piston-assembly dynamics and tribology (compiled part)";
  py::register_exception<io::DeckError>(m, "DeckError", PyExc_ValueError);
  py::register_exception<io::SweepOutputError>(m, "OutputError", PyExc_RuntimeError);
  m.attr("__version__") = io::getVersion();

  py::class_<io::EngineDeck, std::shared_ptr<io::EngineDeck>>(m, "Deck",
                                                              "an engine deck read and checked")
      .def_property_readonly("path", [](const io::EngineDeck& d) { return d.deckPath; })
      .def_property_readonly("overrides", [](const io::EngineDeck& d) { return d.overrides; })
      .def_property_readonly("liner_model", [](const io::EngineDeck& d) { return d.linerModel; })
      .def_property_readonly(
          "inputs",
          [](const io::EngineDeck& d) {
            py::dict out;
            for (const auto& in : d.inputs)
              out[py::str(in.siPath)] = inputValue(in.value);
            return out;
          },
          "every key read (defaults included) in SI, by its SI key path, as summary.json's "
          "inputs")
      .def("__repr__", [](const io::EngineDeck& d) {
        return "<pistondyn.Deck " + d.deckPath + " (" + std::to_string(d.overrides.size()) +
               " overrides)>";
      });

  m.def(
      "_load_deck",
      [](const std::string& path, const std::vector<std::string>& overrides) {
        return std::make_shared<io::EngineDeck>(io::loadEngineDeck(path, overrides));
      },
      py::arg("path"), py::arg("overrides"),
      "Reads and checks a deck with --set-style overrides; raises DeckError listing every "
      "problem (file:line: key: what is wrong).");

  m.def(
      "_run",
      [](const io::EngineDeck& deck, const std::string& outDir) {
        plugin::ResultTableSink rows;
        io::RunOutcome outcome;
        {
          py::gil_scoped_release release;
          outcome = io::runDeck(deck, outDir, {}, {&rows});
        }
        const plugin::ResultTable& t = rows.getTable();
        return runResult(io::makeSummaryJson(deck, outcome), t.columns, t.rows, outDir);
      },
      py::arg("deck"), py::arg("out_dir"),
      "Runs a deck (io::runDeck, as `pistondyn run`); with out_dir not empty also writes "
      "cycle.csv and summary.json there.");

  m.def(
      "_read_results",
      [](const std::string& dir) {
        const io::ResultFolder f = io::readResultFolder(dir);
        return runResult(f.summaryJson, f.cycle.columns, f.cycle.rows, dir);
      },
      py::arg("folder"), "Reads a result folder (cycle.csv, summary.json).");

  m.def(
      "_run_sweep",
      [](const std::string& sweepDeck, const std::string& outDir, int jobs,
         const std::vector<std::string>& overrides) {
        const io::SweepPlan plan = io::loadSweepDeck(sweepDeck, overrides);
        io::SweepOutcome o;
        {
          py::gil_scoped_release release;
          o = io::runSweep(plan, outDir, jobs > 0 ? jobs : io::getAvailableCores());
        }
        py::dict d;
        d["cases"] = o.cases;
        d["earlier"] = o.earlier;
        d["ran"] = o.ran;
        d["failed"] = o.failed;
        std::vector<std::string> folders;
        for (const auto& c : plan.cases)
          folders.push_back(plan.getCaseFolderName(c.index));
        d["case_folders"] = folders;
        return d;
      },
      py::arg("sweep_deck"), py::arg("out_dir"), py::arg("jobs"), py::arg("overrides"),
      "Runs a sweep deck into out_dir (io::runSweep: threads, resume).");
}
