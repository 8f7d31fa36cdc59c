// GoogleTest entry point: OpenFOAM errors throw, so tests can expect them
#include <gtest/gtest.h>
#include "error.H"

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    Foam::FatalError.throwExceptions();
    Foam::FatalIOError.throwExceptions();
    return RUN_ALL_TESTS();
}
