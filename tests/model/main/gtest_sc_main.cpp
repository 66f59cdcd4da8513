// gtest_sc_main.cpp - the entry point of every model test: SystemC's library provides main and
// calls sc_main, which runs the TESTs of the executable (see model_test.h for the pattern).
#include "../model_test.h"

int sc_main(int argc, char *argv[])
{
    testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
