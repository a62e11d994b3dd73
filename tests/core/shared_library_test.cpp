#include "rt/core/shared_library.h"

#include <string>

#include "rt/core/error.h"

#include <gtest/gtest.h>

#include <dlfcn.h>

namespace rt {
namespace {

// The message of the Error that `load` throws ("" when it throws none).
template <typename Load>
std::string error_of(Load load) {
    try {
        load();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(SharedLibrary, FindsAFunctionOfARealLibrary) {
    const SharedLibrary libm("libm.so.6");
    EXPECT_EQ(libm.soname(), "libm.so.6");
    double (*const cosine)(double) = libm.function<double(double)>("cos");
    ASSERT_NE(cosine, nullptr);
    EXPECT_DOUBLE_EQ(cosine(0.0), 1.0);
}

TEST(SharedLibrary, AMissingLibraryIsNamedInTheError) {
    const std::string message =
        error_of([] { const SharedLibrary missing("librt-no-such-library.so.7"); });
    EXPECT_NE(message.find("cannot load librt-no-such-library.so.7: "), std::string::npos)
        << message;
    // dlerror()'s own words follow.
    EXPECT_GT(message.size(), std::string("cannot load librt-no-such-library.so.7: ").size())
        << message;
}

TEST(SharedLibrary, AMissingSymbolIsNamedWithItsLibraryInTheError) {
    const SharedLibrary libm("libm.so.6");
    const std::string message = error_of([&libm] { libm.symbol("rt_no_such_function"); });
    EXPECT_NE(message.find("cannot find rt_no_such_function in libm.so.6: "), std::string::npos)
        << message;
    EXPECT_NE(message.find("undefined symbol"), std::string::npos) << message;  // dlerror()'s
}

// A library opened with SymbolScope::Global lends its symbols to whatever is loaded after it (as
// OpenMPI's components need of libmpi); one opened Local does not. libcrypt is in every Debian
// and linked by none of rt's tests.
TEST(SharedLibrary, OnlyAGlobalLibraryLendsItsSymbolsToOthers) {
    if (dlsym(RTLD_DEFAULT, "crypt") != nullptr) {
        GTEST_SKIP() << "libcrypt is loaded already";
    }
    const SharedLibrary local("libcrypt.so.1", SymbolScope::Local);
    EXPECT_NE(local.symbol("crypt"), nullptr);
    EXPECT_EQ(dlsym(RTLD_DEFAULT, "crypt"), nullptr);
    const SharedLibrary global("libcrypt.so.1", SymbolScope::Global);
    EXPECT_EQ(dlsym(RTLD_DEFAULT, "crypt"), global.symbol("crypt"));
}

}  // namespace
}  // namespace rt
