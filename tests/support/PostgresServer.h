// A throwaway PostgreSQL server for one test suite: initdb into a fresh
// temporary folder, started with pg_ctl on a unix socket only (no TCP), as
// the `postgres` system user when the suite runs as root (PostgreSQL
// refuses to run as root); stopped and removed at the end. Local
// connections are trusted, so roles need no passwords. Never a mock.
#pragma once

#include <csignal>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tactiscope::testing {

class PostgresServer {
public:
    // Throws std::runtime_error with the server's log when it cannot start.
    PostgresServer();
    ~PostgresServer();
    PostgresServer(const PostgresServer&) = delete;
    PostgresServer& operator=(const PostgresServer&) = delete;

    // A libpq connection string to database `dbname` as `user` (the
    // superuser, who owns the cluster, by default).
    std::string conninfo(const std::string& user = kOwner, const std::string& dbname = "postgres") const;

    // The folder of its unix socket (a connection's host).
    std::string folder() const { return m_folder.string(); }

    // Freezes every process of the server (SIGSTOP), as a server or host
    // that stops answering with its connections still open; resume()
    // thaws them (SIGCONT).
    void pause() const { signalAll(SIGSTOP); }
    void resume() const { signalAll(SIGCONT); }

    // Kills every process of the server at once (SIGKILL), as an out-of-
    // memory kill or a power cut of its host would, and waits until they are
    // gone; start() brings it up again on the same data (crash recovery from
    // its write-ahead log). Throws std::runtime_error when it cannot start.
    void crash() const;
    void start() const;

    // CPU seconds the server has used (user and system): the postmaster,
    // the backends it has reaped and those still running.
    double cpuSeconds() const;

    // A hot standby of this server: its data copied by pg_basebackup over
    // the socket, then streaming what this one writes, read-only, on a
    // socket folder of its own. Throws std::runtime_error when it cannot
    // start.
    std::unique_ptr<PostgresServer> standby() const;

    static constexpr const char* kOwner = "tactiscope_owner";

private:
    struct StandbyOf {
        const PostgresServer& primary;
    };
    explicit PostgresServer(StandbyOf primary);
    // A fresh folder the server's user owns.
    void makeFolder();

    // The postmaster, or 0 when it is not running, and its children.
    int postmaster() const;
    std::vector<int> children(int postmaster) const;
    void signalAll(int signal) const;

    std::filesystem::path m_folder;
    std::filesystem::path m_bin;  // initdb, pg_ctl
    std::string m_asPostgres;     // "runuser -u postgres -- " when root
};

// A server holding a central store (`server init`'s schema and roles) in
// its default database, with `logins` made in their roles, e.g.
// {{"press_a", "tactiscope_station"}, {"quality", "tactiscope_reviewer"}}.
std::unique_ptr<PostgresServer> centralStoreServer(const std::vector<std::pair<std::string, std::string>>& logins);

}  // namespace tactiscope::testing
