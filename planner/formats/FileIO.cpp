// Reading plan/project files and writing any output atomically.
#include "formats/FileIO.h"

#include "formats/JsonSupport.h"
#include "formats/PlanIO.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace fc {

namespace fs = std::filesystem;

namespace {

std::string lowerCaseExtension(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

// Writes everything or reports errno; retries short writes and EINTR.
bool writeAll(int fd, const std::string& contents) {
    const char* data = contents.data();
    size_t left = contents.size();
    while (left > 0) {
        const ssize_t written = ::write(fd, data, left);
        if (written < 0) {
            if (errno == EINTR)
                continue;
            return false;
        }
        data += written;
        left -= static_cast<size_t>(written);
    }
    return true;
}

// A new, unique file next to `path` (same directory, so rename is atomic). Created with
// mode 0666 so the umask applies as for any ordinary new file.
int createTemporaryFile(const std::string& path, std::string& temporaryPath) {
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0; attempt < 100; ++attempt) {
        temporaryPath = path + ".tmp-" + std::to_string(::getpid()) + "-" +
                        std::to_string(counter.fetch_add(1));
        const int fd = ::open(temporaryPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    errno = EEXIST;
    return -1;
}

// Makes the rename durable; failures here are not worth failing the write for.
void syncDirectoryOf(const std::string& path) {
    fs::path directory = fs::path(path).parent_path();
    if (directory.empty())
        directory = ".";
    const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

} // namespace

std::string readFile(const std::string& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status))
        throw InputError(path + ": cannot open (no such file)");
    if (fs::is_directory(status))
        throw InputError(path + ": cannot open (it is a directory)");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path + ": cannot open (" + std::strerror(errno) + ")");
    std::ostringstream contents;
    contents << in.rdbuf();
    if (in.bad())
        throw InputError(path + ": cannot read (" + std::strerror(errno) + ")");
    return contents.str();
}

std::string withoutByteOrderMark(std::string text) {
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0)
        text.erase(0, 3);
    return text;
}

void writeFileAtomically(const std::string& path, const std::string& contents) {
    std::string temporaryPath;
    const int fd = createTemporaryFile(path, temporaryPath);
    if (fd < 0)
        throw InputError(
            path + ": cannot write (cannot create a temporary file: " + std::strerror(errno) + ")");
    auto fail = [&](const char* step) {
        const std::string reason = std::strerror(errno);
        ::unlink(temporaryPath.c_str());
        throw InputError(path + ": cannot write (" + step + ": " + reason + ")");
    };
    // Keep the permissions of a file we replace.
    struct stat existing {};
    if (::stat(path.c_str(), &existing) == 0 && S_ISREG(existing.st_mode))
        ::fchmod(fd, existing.st_mode & 07777);
    if (!writeAll(fd, contents)) {
        ::close(fd);
        fail("write failed");
    }
    if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) {
        ::close(fd);
        fail("fsync failed");
    }
    if (::close(fd) != 0)
        fail("close failed");
    if (::rename(temporaryPath.c_str(), path.c_str()) != 0)
        fail("rename failed");
    syncDirectoryOf(path);
}

Project loadProjectFile(const std::string& path, std::optional<int> building) {
    const std::string extension = lowerCaseExtension(path);
    if (extension != ".fcproj" && extension != ".geojson" && extension != ".json")
        throw InputError(path + ": unsupported file type " +
                         (extension.empty() ? "(no extension)" : "\"" + extension + "\"") +
                         "; expected a .fcproj project or a .geojson/.json plan");
    const std::string text = readFile(path);
    Project project;
    try {
        bool isProject = extension == ".fcproj";
        if (extension == ".json") {
            // A .json may hold either; the project names its format.
            const nlohmann::json root = formats::parseJsonDocument(text);
            isProject = root.is_object() && root.contains("format");
        }
        if (isProject && building && *building != 1)
            throw InputError("a project holds one building; --building " +
                             std::to_string(*building) + " does not apply");
        if (isProject)
            project = readProject(text);
        else
            project.plan = readGeoJsonPlan(text, building, &project.notes);
    } catch (const SiteError& e) {
        throw SiteError(path + ": " + e.what(), e.buildingAreas());
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
    project.plan.name = fs::path(path).stem().string();
    return project;
}

} // namespace fc
