// Messages may quote a connection string as typed: a password in it, as a
// key (password=…, quoted or not) or in a URI (user:password@host), is
// hidden before anything prints it. Before, errors echoed it.
#include "core/storage/central/PgConnection.h"

#include <gtest/gtest.h>

using tactiscope::core::storage::central::withoutPasswords;

TEST(ConnectionPasswords, EveryFormOfAPasswordIsHidden)
{
    EXPECT_EQ(withoutPasswords("host=db password=s3cret dbname=tactiscope"), "host=db password=*** dbname=tactiscope");
    EXPECT_EQ(withoutPasswords("host=db PASSWORD = 'se cr\\'et' user=ada"), "host=db PASSWORD = *** user=ada");
    EXPECT_EQ(withoutPasswords("cannot reach postgresql://ada:s3cret@db.site:5432/tactiscope?sslmode=require"),
              "cannot reach postgresql://ada:***@db.site:5432/tactiscope?sslmode=require");
    EXPECT_EQ(withoutPasswords("postgres://db/tactiscope?user=ada&password=s3cret&sslmode=require"),
              "postgres://db/tactiscope?user=ada&password=***&sslmode=require");
    // Nothing else is touched: a user without a password, a port, prose.
    EXPECT_EQ(withoutPasswords("postgresql://ada@db:5432/x and the password file ~/.pgpass"),
              "postgresql://ada@db:5432/x and the password file ~/.pgpass");
}
