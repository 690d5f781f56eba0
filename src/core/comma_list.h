#pragma once
// A comma-separated list as given in an option or a case file
// ("cds,sds,fds", "name=paper,name=corrected"). Empty items (",,", a trailing
// comma) are no items.
#include <string_view>
#include <vector>

namespace rollcheck
{
/// The non-empty items of `list`, in order, as views into `list`.
std::vector<std::string_view> comma_list_items(std::string_view list);
} // namespace rollcheck
