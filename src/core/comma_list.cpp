#include "core/comma_list.h"

namespace rollcheck
{
std::vector<std::string_view> comma_list_items(std::string_view list)
{
  std::vector<std::string_view> items;
  std::size_t start = 0;
  while (start < list.size())
  {
    std::size_t end = list.find(',', start);
    if (end == std::string_view::npos)
      end = list.size();
    if (end > start)
      items.push_back(list.substr(start, end - start));
    start = end + 1;
  }
  return items;
}
} // namespace rollcheck
