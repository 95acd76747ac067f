// The throwaway PostgreSQL server of the central-store tests.
#include "support/PostgresServer.h"

#include "support/TempPath.h"

#include <fstream>
#include <pwd.h>
#include <signal.h>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace tactiscope::testing {
namespace {

// Debian installs the server binaries per version, off the PATH.
std::filesystem::path serverBinaries()
{
    const std::filesystem::path root = "/usr/lib/postgresql";
    std::filesystem::path newest;
    if (std::filesystem::exists(root))
        for (const auto& entry : std::filesystem::directory_iterator(root))
            if (std::filesystem::exists(entry.path() / "bin" / "pg_ctl") && entry.path() > newest)
                newest = entry.path();
    if (newest.empty()) throw std::runtime_error("no PostgreSQL server under /usr/lib/postgresql (install postgresql)");
    return newest / "bin";
}

std::string quoted(const std::string& text)
{
    return "'" + text + "'";
}

std::string fileText(const std::filesystem::path& path)
{
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

PostgresServer::PostgresServer()
    : m_folder(uniqueTempPath("pg")),
      m_bin(serverBinaries())
{
    std::filesystem::remove_all(m_folder);
    std::filesystem::create_directories(m_folder);
    if (::geteuid() == 0) {
        const passwd* postgres = ::getpwnam("postgres");
        if (!postgres) throw std::runtime_error("running as root needs the postgres system user (install postgresql)");
        if (::chown(m_folder.c_str(), postgres->pw_uid, postgres->pw_gid) != 0)
            throw std::runtime_error("cannot give " + m_folder.string() + " to postgres");
        m_asPostgres = "runuser -u postgres -- ";
    }
    // The server writes its own log (as postgres); the commands' output
    // goes to a file of ours.
    const std::string data = (m_folder / "data").string(), log = (m_folder / "server.log").string();
    const std::string output = (m_folder / "commands.txt").string();
    const std::string initdb = m_asPostgres + quoted((m_bin / "initdb").string()) + " -D " + quoted(data) + " -U " +
                               kOwner + " -A trust --no-sync -E UTF8 > " + quoted(output) + " 2>&1";
    if (std::system(initdb.c_str()) != 0) throw std::runtime_error("initdb failed:\n" + fileText(output));
    // A unix socket in the folder only; fsync off: the data die with the test.
    const std::string start = m_asPostgres + quoted((m_bin / "pg_ctl").string()) + " -D " + quoted(data) + " -l " +
                              quoted(log) + " -w -o " +
                              quoted("-c listen_addresses= -c unix_socket_directories=" + m_folder.string() +
                                     " -c fsync=off -c full_page_writes=off") +
                              " start > " + quoted(output) + " 2>&1";
    if (std::system(start.c_str()) != 0)
        throw std::runtime_error("the server did not start:\n" + fileText(output) + fileText(log));
}

PostgresServer::~PostgresServer()
{
    const std::string stop = m_asPostgres + quoted((m_bin / "pg_ctl").string()) + " -D " +
                             quoted((m_folder / "data").string()) + " -m immediate -w stop > /dev/null 2>&1";
    [[maybe_unused]] const int ignored = std::system(stop.c_str());
    std::error_code error;
    std::filesystem::remove_all(m_folder, error);
}

// The postmaster (first line of postmaster.pid) and its children, found in
// /proc by their parent.
void PostgresServer::signalAll(int signal) const
{
    std::ifstream pidFile(m_folder / "data" / "postmaster.pid");
    pid_t postmaster = 0;
    if (!(pidFile >> postmaster) || postmaster <= 0) return;
    ::kill(postmaster, signal);
    for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
        std::ifstream stat(entry.path() / "stat");
        std::string line;
        if (!std::getline(stat, line)) continue;
        // pid (comm) state ppid …: the name may hold spaces, so read after ')'.
        const auto close = line.rfind(')');
        if (close == std::string::npos) continue;
        std::istringstream rest(line.substr(close + 1));
        char state = 0;
        pid_t parent = 0;
        if (rest >> state >> parent && parent == postmaster)
            ::kill(std::stoi(entry.path().filename().string()), signal);
    }
}

std::string PostgresServer::conninfo(const std::string& user, const std::string& dbname) const
{
    return "host=" + m_folder.string() + " dbname=" + dbname + " user=" + user;
}

}  // namespace tactiscope::testing
