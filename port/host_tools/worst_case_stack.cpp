// Worst-case stack depth of a Cortex-M image, from the compiler's stack usage and the
// call graph. No Debian package does this for ARM images (puncover and avstack are not
// packaged), so it is written here, and kept small:
//   - frame sizes: GCC's -fcallgraph-info=su files (.ci; the same numbers as
//     -fstack-usage) for every function compiled with it; for the rest (newlib, libgcc),
//     the stack the disassembled function reserves: push/stmdb, vpush/vstmdb, sub sp,
//     and pre-indexed stores to sp, all summed (an over-estimate where paths differ);
//   - calls: every bl/blx to a symbol and every branch to another function's start (a
//     tail call) in the disassembly of the linked image, which is the truth after
//     inlining; indirect calls (blx/bx through a register) are resolved to the --indirect
//     candidates, the only function pointers the program passes; a function pointer that
//     one call site alone takes (a driver's sample sink) is given as --call CALLER=CALLEE,
//     an edge of its own, since as an --indirect candidate every indirect call would reach
//     it;
//   - total: the deepest path from --root, plus for each --interrupt handler its own
//     deepest path and the 36-byte basic exception frame (8 words, and the aligner word
//     when the stack was not 8-byte aligned; PM0214 §2.3.7). Handlers are summed, as if
//     each could nest on the last. The basic frame is the whole frame because the startup
//     code clears FPCCR.ASPEN (port/cortex_m/startup.cpp), which is sound only while no
//     handler uses the FPU: so the program fails when any function a handler reaches
//     holds an FPU instruction (a `v` mnemonic, or a coprocessor access to p10/p11), or
//     an indirect call it cannot follow. With ASPEN set, each frame would be 108 bytes
//     (26 words: S0-S15 and FPSCR too, and the aligner).
// Recursion makes the depth unbounded; the program says so and exits 1.
//   worst_case_stack DISASSEMBLY.txt [--ci FILE]... --root SYMBOL [--interrupt SYMBOL]...
//                    [--indirect SYMBOL]... [--call CALLER=CALLEE]... [--report SYMBOL]...
// Writes "key value" lines: stack_bytes, root_bytes, interrupt_bytes, then the deepest
// path, and the depth below each --report function.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Function {
  long frame_from_disassembly = 0;
  long frame_from_compiler = -1;  // -1: not compiled with -fcallgraph-info
  bool dynamic_frame = false;
  bool indirect_calls = false;
  bool uses_fpu = false;  // holds an FPU instruction
  std::set<std::string> callees;
  long frame() const { return frame_from_compiler >= 0 ? frame_from_compiler : frame_from_disassembly; }
};

std::map<std::string, Function> functions;
std::vector<std::string> indirect_targets;

int count_registers(const std::string& list) {
  // "{r4, r5, lr}" or "{d8-d15}" or "{s16-s23}"; d registers are 8 bytes, the rest 4.
  static const std::regex item(R"(([rdsa-z]+)(\d*)(?:-[a-z]+(\d+))?)");
  int bytes = 0;
  for (std::sregex_iterator it(list.begin(), list.end(), item), end; it != end; ++it) {
    const std::string name = (*it)[1];
    const int width = name == "d" ? 8 : 4;
    int count = 1;
    if ((*it)[3].matched) count = std::stoi((*it)[3]) - std::stoi((*it)[2]) + 1;
    bytes += width * count;
  }
  return bytes;
}

void read_disassembly(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  static const std::regex header(R"(^[0-9a-f]+ <([^>]+)>:$)");
  static const std::regex insn(R"(^\s+[0-9a-f]+:\s+(\S+)\s*(.*)$)");
  static const std::regex call_target(R"(<([^>+]+)(\+0x[0-9a-f]+)?>)");
  static const std::regex sub_sp(R"(^sub(?:w|\.w)?$)");
  std::string line;
  std::string current;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, header)) {
      current = m[1];
      functions[current];
      continue;
    }
    if (current.empty() || !std::regex_match(line, m, insn)) continue;
    const std::string op = m[1];
    const std::string args = m[2];
    Function& f = functions[current];
    if (op.rfind("push", 0) == 0 || op.rfind("vpush", 0) == 0 ||
        ((op.rfind("stmdb", 0) == 0 || op.rfind("vstmdb", 0) == 0) && args.rfind("sp!", 0) == 0)) {
      f.frame_from_disassembly += count_registers(args.substr(args.find('{')));
    } else if (std::regex_match(op, sub_sp) && args.rfind("sp, ", 0) == 0) {
      const auto hash = args.find('#');
      if (hash != std::string::npos) f.frame_from_disassembly += std::stol(args.substr(hash + 1), nullptr, 0);
    } else if (op.rfind("str", 0) == 0 && args.find("[sp, #-") != std::string::npos && args.back() == '!') {
      f.frame_from_disassembly += std::stol(args.substr(args.find("#-") + 2), nullptr, 0);
    }
    if (op[0] == 'v' || ((op.rfind("mcr", 0) == 0 || op.rfind("mrc", 0) == 0 || op.rfind("ldc", 0) == 0 ||
                          op.rfind("stc", 0) == 0 || op.rfind("cdp", 0) == 0) &&
                         (args.find("p10") != std::string::npos || args.find("p11") != std::string::npos))) {
      f.uses_fpu = true;
    }
    const bool is_call = op == "bl" || op == "blx";
    const bool is_branch = !is_call && op[0] == 'b' && op.rfind("bic", 0) != 0 && op.rfind("bkpt", 0) != 0 &&
                           op.rfind("bfi", 0) != 0 && op.rfind("bfc", 0) != 0;
    std::smatch target;
    if ((is_call || is_branch) && std::regex_search(args, target, call_target)) {
      const std::string callee = target[1];
      // A branch to another function's very start is a tail call; within one, a jump.
      if (is_call || (callee != current && !target[2].matched)) f.callees.insert(callee);
    } else if ((op == "blx" || op.rfind("bx", 0) == 0) && args != "lr") {
      f.indirect_calls = true;
    }
  }
}

void read_call_graph_info(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  static const std::regex node(
      R"re(^node: \{ title: "(?:[^"]*:)?([^":]+)" label: "[^"]*\\n(\d+) bytes \(([a-z,]+)\))re");
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (!std::regex_search(line, m, node)) continue;
    auto it = functions.find(m[1]);
    if (it == functions.end()) continue;  // not in the image (inlined or dropped)
    it->second.frame_from_compiler = std::max(it->second.frame_from_compiler, std::stol(m[2]));
    const std::string qualifier = m[3];
    if (qualifier.find("dynamic") != std::string::npos && qualifier.find("bounded") == std::string::npos) {
      it->second.dynamic_frame = true;
    }
  }
}

struct Depth {
  long bytes = 0;
  std::vector<std::string> path;
};

std::map<std::string, Depth> memo;
std::set<std::string> on_path;

Depth deepest(const std::string& name) {
  if (auto it = memo.find(name); it != memo.end()) return it->second;
  const auto fit = functions.find(name);
  if (fit == functions.end()) return {};  // an absolute address or a data symbol
  if (on_path.count(name)) throw std::runtime_error("recursion through " + name + ": unbounded stack");
  if (fit->second.dynamic_frame) throw std::runtime_error(name + " has a dynamic frame: unbounded stack");
  on_path.insert(name);
  std::set<std::string> callees = fit->second.callees;
  if (fit->second.indirect_calls) callees.insert(indirect_targets.begin(), indirect_targets.end());
  Depth best;
  for (const std::string& callee : callees) {
    const Depth d = deepest(callee);
    if (d.bytes > best.bytes || best.path.empty()) best = d;
  }
  on_path.erase(name);
  best.bytes += fit->second.frame();
  best.path.insert(best.path.begin(), name);
  memo[name] = best;
  return best;
}

// The first function reachable from `name` (itself included) that holds an FPU
// instruction or an indirect call (which could reach one), or "" when there is none.
std::string reaches_fpu(const std::string& name, std::set<std::string>& seen) {
  const auto fit = functions.find(name);
  if (fit == functions.end() || !seen.insert(name).second) return "";
  if (fit->second.uses_fpu) return name + " (an FPU instruction)";
  if (fit->second.indirect_calls) return name + " (an indirect call)";
  for (const std::string& callee : fit->second.callees) {
    const std::string found = reaches_fpu(callee, seen);
    if (!found.empty()) return found;
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: worst_case_stack DISASSEMBLY.txt [--ci F]... --root S [--interrupt S]... "
                 "[--indirect S]... [--call CALLER=CALLEE]... [--report S]...\n";
    return 2;
  }
  try {
    read_disassembly(argv[1]);
    std::string root;
    std::vector<std::string> interrupts, reports, ci_files;
    std::vector<std::pair<std::string, std::string>> calls;
    for (int i = 2; i + 1 < argc; i += 2) {
      const std::string option = argv[i];
      const std::string value = argv[i + 1];
      if (option == "--ci")
        ci_files.push_back(value);
      else if (option == "--root")
        root = value;
      else if (option == "--interrupt")
        interrupts.push_back(value);
      else if (option == "--indirect")
        indirect_targets.push_back(value);
      else if (option == "--report")
        reports.push_back(value);
      else if (option == "--call" && value.find('=') != std::string::npos)
        calls.emplace_back(value.substr(0, value.find('=')), value.substr(value.find('=') + 1));
      else
        throw std::runtime_error("unknown option " + option);
    }
    for (const auto& f : ci_files) read_call_graph_info(f);
    for (const auto& [caller, callee] : calls) {
      if (!functions.count(caller) || !functions.count(callee))
        throw std::runtime_error("--call " + caller + "=" + callee + ": not in the image");
      functions[caller].callees.insert(callee);
    }
    for (const auto& s : std::vector<std::string>{root}) {
      if (!functions.count(s)) throw std::runtime_error("root " + s + " is not in the image");
    }
    // 8 words and the aligner (file comment): the frame of a core that stacks no FP context.
    constexpr long exception_frame_bytes = 36;
    const Depth main_path = deepest(root);
    long interrupt_bytes = 0;
    for (const auto& handler : interrupts) {
      if (!functions.count(handler)) throw std::runtime_error(handler + " is not in the image");
      std::set<std::string> seen;
      const std::string fpu = reaches_fpu(handler, seen);
      if (!fpu.empty()) {
        throw std::runtime_error(
            "interrupt " + handler + " reaches " + fpu +
            ": the FPU context would have to be stacked (FPCCR.ASPEN set, a 108-byte frame)");
      }
      interrupt_bytes += exception_frame_bytes + deepest(handler).bytes;
    }
    int from_compiler = 0;
    for (const auto& [name, f] : functions) from_compiler += f.frame_from_compiler >= 0;
    std::printf("stack_bytes %ld\n", main_path.bytes + interrupt_bytes);
    std::printf("root_bytes %ld\n", main_path.bytes);
    std::printf("interrupt_bytes %ld\n", interrupt_bytes);
    std::printf("functions %zu\n", functions.size());
    std::printf("frames_from_compiler %d\n", from_compiler);
    for (const auto& name : main_path.path) {
      const Function& f = functions[name];
      std::printf("path %s %ld %s\n", name.c_str(), f.frame(),
                  f.frame_from_compiler >= 0 ? "compiler" : "disassembly");
    }
    for (const auto& name : reports) {
      if (functions.count(name)) std::printf("below %s %ld\n", name.c_str(), deepest(name).bytes);
    }
  } catch (const std::exception& e) {
    std::cerr << "worst_case_stack: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
