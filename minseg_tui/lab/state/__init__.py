"""A session's state: the session, its entries, what it computes, Task 4's capture and the Task 10 procedure."""
