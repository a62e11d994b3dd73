#include "command_line/command_line.h"

#include <cstdint>
#include <exception>
#include <iostream>
#include <memory>
#include <utility>

#include "rt/core/error.h"
#include "rt/core/text.h"

#include <fmt/format.h>

namespace rt::cli {

namespace {

// CLI11's help, with the usage line given by the program when CLI11 cannot know it: the programs
// that pass arguments on to rt have a SCENE and switches that CLI11 never declares.
class Formatter : public CLI::Formatter {
public:
    explicit Formatter(std::string usage) : usage_(std::move(usage)) { column_width(26); }

    std::string make_usage(const CLI::App* app, std::string name) const override {
        if (usage_.empty()) {
            return CLI::Formatter::make_usage(app, std::move(name));
        }
        return fmt::format("Usage: {} {}\n", name, usage_);
    }

private:
    std::string usage_;
};

}  // namespace

void configure(CLI::App& app, std::string usage) {
    app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    app.formatter(std::make_shared<Formatter>(std::move(usage)));
}

std::optional<int> parse(CLI::App& app, int argc, const char* const* argv, BareCommand bare) {
    if (argc <= 1 && bare == BareCommand::PrintsHelp) {
        std::cout << app.help();
        return 0;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::cout << app.help();
        return 0;
    } catch (const CLI::ParseError& e) {
        const std::string& name = app.get_name();
        std::cerr << fmt::format("{}: {}\n{}: run '{} --help' for the options\n", name, e.what(),
                                 name, name);
        return kUsageExit;
    }
    return std::nullopt;
}

CLI::Validator number_at_least(double least) {
    return {[least](std::string& text) -> std::string {
                const std::optional<double> value = parse_double(text);
                if (value && *value >= least) {
                    return {};
                }
                return fmt::format("expected a number of at least {}, found {}", least,
                                   quote_token(text));
            },
            ""};
}

CLI::Validator number_above(double bound) {
    return {[bound](std::string& text) -> std::string {
                const std::optional<double> value = parse_double(text);
                if (value && *value > bound) {
                    return {};
                }
                return fmt::format("expected a number above {}, found {}", bound,
                                   quote_token(text));
            },
            ""};
}

CLI::Validator whole_number_at_least(long long least) {
    return {[least](std::string& text) -> std::string {
                const std::optional<std::int64_t> value = parse_integer(text);
                if (value && *value >= least) {
                    text = std::to_string(*value);
                    return {};
                }
                return fmt::format("expected a whole number of at least {}, found {}", least,
                                   quote_token(text));
            },
            ""};
}

int exit_code_of(std::string_view program, const std::function<int()>& body,
                 std::string_view usage_hint) {
    const auto print = [&](std::string_view message) {
        std::cerr << program << ": " << message << '\n';
    };
    try {
        return body();
    } catch (const InputError& e) {
        print(e.what());
        return kBadInputExit;
    } catch (const UsageError& e) {
        print(e.what());
        if (!usage_hint.empty()) {
            print(usage_hint);
        }
        return kUsageExit;
    } catch (const NotImplementedError& e) {
        print(e.what());
        return kUsageExit;
    } catch (const IoError& e) {
        print(e.what());
        return kIoExit;
    } catch (const std::exception& e) {
        print(std::string("internal error: ") + e.what());
        return kInternalExit;
    }
}

}  // namespace rt::cli
