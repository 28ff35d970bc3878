#pragma once
// CLI11's App, declared for the headers that only pass it on: CLI/App.hpp is slow to compile, so
// only the files that register options include it.
namespace CLI {
class App;
}
