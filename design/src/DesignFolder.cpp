#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "FileBytes.h"
#include "pistondyn/design/DesignStudy.h"
#include "pistondyn/io/ResultWriters.h"

namespace pistondyn::design {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

const char* kDesignJson = "design.json";

std::shared_ptr<const void> lockFolder(const fs::path& folder) {
  const std::string path = (folder / ".design.lock").string();
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error(path + ": cannot create the study's lock file");
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
    ::close(fd);
    throw DesignOutputError(folder.string() +
                            " is in use by another pistondyn study running now (it holds " + path +
                            "); wait for it to end, or use another folder");
  }
  return std::shared_ptr<const void>(new int(fd), [](const void* p) {
    const int* handle = static_cast<const int*>(p);
    ::close(*handle);
    delete handle;
  });
}

// The entries of two study descriptions that differ, in words.
std::string describeDifference(const Json& stored, const Json& now) {
  std::string why;
  for (const auto& [key, value] : now.items()) {
    if (!stored.contains(key) || stored[key] != value)
      why += (why.empty() ? "" : ", ") + key;
  }
  for (const auto& [key, value] : stored.items()) {
    if (!now.contains(key))
      why += (why.empty() ? "" : ", ") + key;
  }
  return why.empty() ? "its fingerprint differs" : "it differs in " + why;
}

const char* article(const std::string& kind) {
  return kind == "optimize" ? "an optimisation" : kind == "fit" ? "a fit" : "a propagation";
}

}  // namespace

DesignFolder openDesignFolder(const std::string& dir, const std::string& kind,
                              const std::string& fingerprint, const std::string& description) {
  const fs::path folder(dir);
  std::error_code ec;
  DesignFolder out;
  out.dir = fs::absolute(folder, ec).lexically_normal().string();
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
    throw DesignOutputError(dir + " is not a folder");
  const Json now = Json::parse(description);
  if (fs::is_directory(folder, ec)) {
    const fs::path stored = folder / kDesignJson;
    if (fs::exists(stored, ec)) {
      const auto text = io::detail::readFileBytes(stored.string());
      Json j;
      try {
        j = Json::parse(text.value_or(""));
        (void)j.at("fingerprint").get<std::string>();
        (void)j.at("kind").get<std::string>();
      } catch (const nlohmann::json::exception&) {
        throw DesignOutputError(stored.string() +
                                " cannot be read as a study's description; use another --out "
                                "folder");
      }
      const std::string storedKind = j["kind"].get<std::string>();
      if (storedKind != kind)
        throw DesignOutputError(dir + " holds " + article(storedKind) + ", not " + article(kind) +
                                " (its design.json); use another --out folder");
      if (j["fingerprint"].get<std::string>() != fingerprint) {
        const Json storedStudy = j.value("study", Json::object());
        throw DesignOutputError(
            dir + " holds the results of a different " +
            std::string(article(kind)).substr(std::string(article(kind)).find(' ') + 1) + " (" +
            storedStudy.value("deck", std::string("?")) +
            "): " + describeDifference(storedStudy, now) +
            ". Results of different studies are never mixed: use another --out folder, or delete "
            "this one to start afresh");
      }
      out.resumed = true;
    } else if (fs::directory_iterator(folder, ec) != fs::directory_iterator()) {
      throw DesignOutputError(dir +
                              " is not empty and holds no design.json: not the output folder of "
                              "a study; use a new or empty folder");
    }
  }
  if (!out.resumed) {
    Json j;
    j["format"] = "pistondyn design 1";
    j["kind"] = kind;
    j["fingerprint"] = fingerprint;
    j["study"] = now;
    io::writeFilesAtomically(
        dir, {{kDesignJson, j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"}});
  }
  out.lock = lockFolder(folder);
  return out;
}

}  // namespace pistondyn::design
