// conservation_check_test.cpp - the end-of-run conservation check (model/run/model_run.h) is an
// internal check: a ledger with a packet created and never consumed fails it as a bug of the
// model (InternalError naming the check's file and line and the counts), not as a user error.
#include <string>

#include "internal_check.h"
#include "model_run.h"
#include "model_test.h"
#include "packet_ledger.h"
#include "user_error.h"

using namespace torusrt;

TEST(ConservationCheck, BalancedLedgerPasses)
{
    PacketLedger ledger;
    ledger.created(RT_PACKET_RAY);
    ledger.consumed(RT_PACKET_RAY, sc_core::SC_ZERO_TIME);
    EXPECT_NO_THROW(check_conservation(ledger));
}

TEST(ConservationCheck, LostPacketIsAnInternalError)
{
    PacketLedger ledger;
    ledger.created(RT_PACKET_RAY);
    ledger.created(RT_PACKET_SHADOW);
    ledger.consumed(RT_PACKET_RAY, sc_core::SC_ZERO_TIME);
    try {
        check_conservation(ledger);
        FAIL() << "no error for a packet that was never consumed";
    } catch (const UserError &) {
        FAIL() << "reported as the user's error";
    } catch (const InternalError &e) {
        std::string what = e.what();
        EXPECT_NE(what.find("internal error"), std::string::npos) << what;
        EXPECT_NE(what.find("model_run.cpp:"), std::string::npos) << what;
        EXPECT_NE(what.find("created 2, consumed 1"), std::string::npos) << what;
    }
}
