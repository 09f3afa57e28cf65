// FMI 3.0 archive rules (docs/fmi3-rules.md §1, §6): the binary under the platform tuple
// x86_64-linux, and the functions its ELF dynamic symbol table exports.
#include <elf.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <set>

#include "model_description_check3.hpp"
#include "stride/fmi3/fmi3_api.h"
#include "xs_values.hpp"

namespace stride::fmi_check::detail {

namespace {

/// Every function of the FMI 3.0 C API: a binary exports all of them, whichever interface
/// types and capabilities it offers (fmi3-rules.md §1).
const std::vector<std::string_view>& fmi3_functions() {
#define STRIDE_FMI3_NAME(name) #name,
  static const std::vector<std::string_view> names = {STRIDE_FMI3_FUNCTIONS(STRIDE_FMI3_NAME)};
#undef STRIDE_FMI3_NAME
  return names;
}

/// A copy of the T at `offset`, when `bytes` holds it whole (ELF fields need not be aligned
/// in a buffer read from a ZIP entry).
template <class T>
std::optional<T> read_at(std::string_view bytes, std::uint64_t offset) {
  if (offset > bytes.size() || bytes.size() - offset < sizeof(T)) return std::nullopt;
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

std::optional<Elf64_Shdr> section(std::string_view bytes, const Elf64_Ehdr& header,
                                  std::uint64_t index) {
  if (index >= header.e_shnum) return std::nullopt;
  return read_at<Elf64_Shdr>(bytes, header.e_shoff + index * sizeof(Elf64_Shdr));
}

/// Name -> whether it is a function, of each defined global or weak symbol of .dynsym;
/// nullopt with `problem` set when the bytes are no readable x86-64 ELF shared object.
std::optional<std::map<std::string, bool, std::less<>>> dynamic_symbols(std::string_view bytes,
                                                                        std::string& problem) {
  const auto header = read_at<Elf64_Ehdr>(bytes, 0);
  if (!header || std::memcmp(header->e_ident, ELFMAG, SELFMAG) != 0) {
    problem = "is not an ELF file";
    return std::nullopt;
  }
  if (header->e_ident[EI_CLASS] != ELFCLASS64 || header->e_ident[EI_DATA] != ELFDATA2LSB ||
      header->e_machine != EM_X86_64 || header->e_type != ET_DYN) {
    problem = "is not a 64-bit little-endian x86-64 shared object";
    return std::nullopt;
  }
  if (header->e_shentsize != sizeof(Elf64_Shdr)) {
    problem = "has section headers of an unexpected size";
    return std::nullopt;
  }
  for (std::uint64_t i = 0; i < header->e_shnum; ++i) {
    const auto dynsym = section(bytes, *header, i);
    if (!dynsym) break;
    if (dynsym->sh_type != SHT_DYNSYM) continue;
    const auto strtab = section(bytes, *header, dynsym->sh_link);
    if (!strtab || strtab->sh_offset > bytes.size() ||
        bytes.size() - strtab->sh_offset < strtab->sh_size ||
        dynsym->sh_entsize != sizeof(Elf64_Sym)) {
      break;
    }
    const std::string_view strings = bytes.substr(strtab->sh_offset, strtab->sh_size);
    std::map<std::string, bool, std::less<>> symbols;
    for (std::uint64_t s = 0; s < dynsym->sh_size / sizeof(Elf64_Sym); ++s) {
      const auto sym = read_at<Elf64_Sym>(bytes, dynsym->sh_offset + s * sizeof(Elf64_Sym));
      if (!sym || sym->st_name >= strings.size()) break;
      const unsigned bind = ELF64_ST_BIND(sym->st_info);
      const unsigned type = ELF64_ST_TYPE(sym->st_info);
      const bool visible = ELF64_ST_VISIBILITY(sym->st_other) == STV_DEFAULT ||
                           ELF64_ST_VISIBILITY(sym->st_other) == STV_PROTECTED;
      if (sym->st_shndx == SHN_UNDEF || !visible || (bind != STB_GLOBAL && bind != STB_WEAK)) {
        continue;
      }
      const std::string_view rest = strings.substr(sym->st_name);
      const std::string name(rest.substr(0, rest.find('\0')));
      symbols[name] = type == STT_FUNC || type == STT_GNU_IFUNC;
    }
    return symbols;
  }
  problem = "has no readable dynamic symbol table (.dynsym)";
  return std::nullopt;
}

}  // namespace

void check_archive_ties3(reporter& out, const archive_listing& archive,
                         std::string_view model_identifier, std::string_view me_model_identifier) {
  // FMI 2.0 platform folders, which an FMI 3.0 importer does not look into
  static const std::map<std::string_view, std::string_view> k_fmi2_folders = {
      {"linux64", "x86_64-linux"},
      {"linux32", "x86-linux"},
      {"win64", "x86_64-windows"},
      {"win32", "x86-windows"},
      {"darwin64", "x86_64-darwin"}};
  const std::array<binary_name, 2> binaries{
      {{model_identifier, "CoSimulation"}, {me_model_identifier, "ModelExchange"}}};
  check_binary_layout(
      out, archive, binaries,
      {"x86_64-linux", k_fmi2_folders, "an FMI 2.0 platform folder", "FMI 3.0", "fmi3."});
}

void check_exports3(reporter& out, std::string_view entry, std::string_view bytes) {
  std::string problem;
  const auto symbols = dynamic_symbols(bytes, problem);
  if (!symbols) {
    out.error("fmi3.exports.elf", quote(entry) + " " + problem);
    return;
  }
  std::string missing;
  std::size_t missing_count = 0;
  for (std::string_view name : fmi3_functions()) {
    const auto it = symbols->find(name);
    if (it == symbols->end()) {
      missing += (missing.empty() ? "" : ", ") + std::string(name);
      ++missing_count;
    } else if (!it->second) {
      out.error("fmi3.exports.functions",
                quote(entry) + " exports " + std::string(name) + ", but not as a function");
    }
  }
  if (missing_count > 0) {
    out.error("fmi3.exports.functions", quote(entry) + " does not export " +
                                            std::to_string(missing_count) + " of the " +
                                            std::to_string(fmi3_functions().size()) +
                                            " FMI 3.0 functions every FMU must export: " + missing);
  }
}

}  // namespace stride::fmi_check::detail
