#define BOOST_TEST_MODULE verify_turning
#include <boost/test/unit_test.hpp>
BOOST_AUTO_TEST_CASE(placeholder) {}
