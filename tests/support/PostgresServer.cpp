// The throwaway PostgreSQL server of the central-store tests.
#include "support/PostgresServer.h"

#include "support/TempPath.h"

#include "core/storage/central/CentralSchema.h"
#include "core/storage/central/PgConnection.h"

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

void PostgresServer::makeFolder()
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
}

PostgresServer::PostgresServer()
    : m_folder(uniqueTempPath("pg")),
      m_bin(serverBinaries())
{
    makeFolder();
    // The server writes its own log (as postgres); the commands' output
    // goes to a file of ours.
    const std::string data = (m_folder / "data").string();
    const std::string output = (m_folder / "commands.txt").string();
    const std::string initdb = m_asPostgres + quoted((m_bin / "initdb").string()) + " -D " + quoted(data) + " -U " +
                               kOwner + " -A trust --no-sync -E UTF8 > " + quoted(output) + " 2>&1";
    if (std::system(initdb.c_str()) != 0) throw std::runtime_error("initdb failed:\n" + fileText(output));
    start();
}

PostgresServer::PostgresServer(StandbyOf of)
    : m_folder(uniqueTempPath("pg-standby")),
      m_bin(of.primary.m_bin)
{
    makeFolder();
    // -R: started as a standby streaming from the primary (initdb's
    // pg_hba trusts local replication connections).
    const std::string data = (m_folder / "data").string();
    const std::string output = (m_folder / "commands.txt").string();
    const std::string copy = m_asPostgres + quoted((m_bin / "pg_basebackup").string()) + " -h " +
                             quoted(of.primary.folder()) + " -U " + kOwner + " -D " + quoted(data) +
                             " -R -X stream --checkpoint=fast --no-sync > " + quoted(output) + " 2>&1";
    if (std::system(copy.c_str()) != 0) throw std::runtime_error("pg_basebackup failed:\n" + fileText(output));
    start();
}

std::unique_ptr<PostgresServer> PostgresServer::standby() const
{
    return std::unique_ptr<PostgresServer>(new PostgresServer(StandbyOf{*this}));
}

void PostgresServer::start() const
{
    // A unix socket in the folder only; fsync off: the data die with the
    // test. Room for a site's hundred stations at once and a few more.
    const std::string data = (m_folder / "data").string(), log = (m_folder / "server.log").string();
    const std::string output = (m_folder / "commands.txt").string();
    const std::string start = m_asPostgres + quoted((m_bin / "pg_ctl").string()) + " -D " + quoted(data) + " -l " +
                              quoted(log) + " -w -o " +
                              quoted("-c listen_addresses= -c unix_socket_directories=" + m_folder.string() +
                                     " -c fsync=off -c full_page_writes=off -c max_connections=130") +
                              " start > " + quoted(output) + " 2>&1";
    if (std::system(start.c_str()) != 0)
        throw std::runtime_error("the server did not start:\n" + fileText(output) + fileText(log));
}

void PostgresServer::crash() const
{
    const int pid = postmaster();
    if (pid == 0) return;
    std::vector<int> all = children(pid);
    all.push_back(pid);
    for (const int p : all) ::kill(p, SIGKILL);
    // Gone once /proc no longer lists them (init reaps the orphans).
    for (int wait = 0; wait < 1000; ++wait) {
        bool alive = false;
        for (const int p : all) alive = alive || std::filesystem::exists("/proc/" + std::to_string(p));
        if (!alive) return;
        ::usleep(10000);
    }
    throw std::runtime_error("the server's processes outlived SIGKILL for 10 s");
}

PostgresServer::~PostgresServer()
{
    const std::string stop = m_asPostgres + quoted((m_bin / "pg_ctl").string()) + " -D " +
                             quoted((m_folder / "data").string()) + " -m immediate -w stop > /dev/null 2>&1";
    [[maybe_unused]] const int ignored = std::system(stop.c_str());
    std::error_code error;
    std::filesystem::remove_all(m_folder, error);
}

// The postmaster: the first line of postmaster.pid, if that process lives.
int PostgresServer::postmaster() const
{
    std::ifstream pidFile(m_folder / "data" / "postmaster.pid");
    pid_t pid = 0;
    if (!(pidFile >> pid) || pid <= 0 || ::kill(pid, 0) != 0) return 0;
    return pid;
}

namespace {

// The fields of /proc/PID/stat after the name (which may hold spaces), the
// first being the state; empty when the process is gone.
std::vector<std::string> statFields(const std::filesystem::path& proc)
{
    std::ifstream stat(proc / "stat");
    std::string line;
    std::vector<std::string> fields;
    if (!std::getline(stat, line)) return fields;
    const auto close = line.rfind(')');
    if (close == std::string::npos) return fields;
    std::istringstream rest(line.substr(close + 1));
    for (std::string field; rest >> field;) fields.push_back(field);
    return fields;
}

}  // namespace

std::vector<int> PostgresServer::children(int parent) const
{
    std::vector<int> result;
    for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
        const auto fields = statFields(entry.path());
        if (fields.size() > 1 && std::stoi(fields[1]) == parent)
            result.push_back(std::stoi(entry.path().filename().string()));
    }
    return result;
}

void PostgresServer::signalAll(int signal) const
{
    const int pid = postmaster();
    if (pid == 0) return;
    ::kill(pid, signal);
    for (const int child : children(pid)) ::kill(child, signal);
}

double PostgresServer::cpuSeconds() const
{
    // utime, stime, cutime, cstime are fields 14 to 17 of stat: 11 to 14
    // after the state (field 3).
    const auto ticks = [](int pid, bool reaped) {
        const auto fields = statFields("/proc/" + std::to_string(pid));
        if (fields.size() < 15) return 0.0;
        double sum = std::stod(fields[11]) + std::stod(fields[12]);
        if (reaped) sum += std::stod(fields[13]) + std::stod(fields[14]);
        return sum;
    };
    const int pid = postmaster();
    if (pid == 0) return 0.0;
    double total = ticks(pid, true);
    for (const int child : children(pid)) total += ticks(child, false);
    return total / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

std::string PostgresServer::conninfo(const std::string& user, const std::string& dbname) const
{
    return "host=" + m_folder.string() + " dbname=" + dbname + " user=" + user;
}

std::unique_ptr<PostgresServer> centralStoreServer(const std::vector<std::pair<std::string, std::string>>& logins)
{
    auto server = std::make_unique<PostgresServer>();
    core::storage::central::PgConnection owner(server->conninfo());
    core::storage::central::initCentralStore(owner);
    std::string roles;
    for (const auto& [login, role] : logins) roles += "CREATE ROLE " + login + " LOGIN IN ROLE " + role + ";\n";
    owner.run(roles);
    return server;
}

}  // namespace tactiscope::testing
